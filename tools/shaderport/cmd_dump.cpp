#include <cstdio>
#include <string>

#include "cli_errors.h"
#include "commands.h"
#include "driver/dump.h"
#include "driver/input_files.h"
#include "report/output_format.h"

namespace shaderport::cli {
namespace {

struct DumpArgs {
  std::string path;
  bool tokens = false;
  bool pp_tokens = false;
  bool ast = false;
  bool types = false;
};

int RunDump(const DumpArgs& args) {
  const int chosen = int{args.tokens} + int{args.pp_tokens} + int{args.ast} + int{args.types};
  if (chosen != 1) {
    return UsageError("give exactly one of --tokens, --pp-tokens, --ast, --types");
  }
  driver::DumpKind kind = driver::DumpKind::kTypes;
  if (args.tokens) kind = driver::DumpKind::kTokens;
  if (args.pp_tokens) kind = driver::DumpKind::kPpTokens;
  if (args.ast) kind = driver::DumpKind::kAst;

  if (const std::string missing = driver::MissingPathError(args.path); !missing.empty()) {
    return UsageError(missing);
  }
  SourceManager sources;
  driver::DumpResult result = driver::DumpFile(args.path, kind, sources);
  std::fwrite(result.text.data(), 1, result.text.size(), stdout);
  std::fflush(stdout);
  if (result.diagnostics.diagnostics.empty()) return kExitOk;
  CheckReport report;
  report.sources = &sources;
  report.files.push_back(std::move(result.diagnostics));
  SortReport(report);
  ReportOptions options;
  options.tool_version = SHADERPORT_VERSION;
  const std::string text = FormatReport(report, OutputFormat::kText, options);
  std::fwrite(text.data(), 1, text.size(), stderr);
  return HasErrors(report.files.front().diagnostics) ? kExitFindings : kExitOk;
}

}  // namespace

void AddDumpCommand(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<DumpArgs>();
  auto* command = app.add_subcommand("dump", "Print the front end's view of one shader");
  command->add_option("file", args->path, "Shader file")->required();
  command->add_flag("--tokens", args->tokens, "Lexed tokens with their positions");
  command->add_flag("--pp-tokens", args->pp_tokens, "Tokens after preprocessing");
  command->add_flag("--ast", args->ast, "The syntax tree with source ranges");
  command->add_flag("--types", args->types, "The type of every expression");
  command->callback([args, &exit_code] { exit_code = RunDump(*args); });
}

}  // namespace shaderport::cli
