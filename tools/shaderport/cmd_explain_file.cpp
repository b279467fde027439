// `shaderport explain-file`: what each file was decided to be (dialect, pass,
// stage, harness, channel types, target) and why, made by the same run `check` makes.
#include <algorithm>
#include <array>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cli_errors.h"
#include "commands.h"
#include "driver/check_pipeline.h"
#include "empty_input.h"
#include "option_names.h"
#include "port_arguments.h"
#include "report/check_report.h"

namespace shaderport::cli {
namespace {

struct ExplainArgs {
  std::vector<std::string> paths;
  std::string format = "text";
  std::string dialect;
  std::string stage;
  std::string target;
  std::vector<std::string> channels;
  std::string common;
  std::string config;
  bool no_config = false;
};

const std::array<std::string, 2> kExplainFormats = {"text", "json"};

std::string PrintableName(const FileReport& report) {
  return report.file != nullptr ? std::string(report.file->Name()) : std::string();
}

void PrintText(const CheckReport& report) {
  for (const FileReport& file : report.files) {
    if (file.role == FileRole::kInput) continue;  // a config file's problems
    std::printf("%s\n", PrintableName(file).c_str());
    for (const DecisionPart& part : file.decision) {
      std::printf("  %-10s %-14s %s\n", part.part.c_str(), part.value.c_str(),
                  part.because.c_str());
    }
    for (const Diagnostic& diagnostic : file.diagnostics) {
      std::printf("  (not decided: %s [%s])\n", diagnostic.message.c_str(),
                  diagnostic.rule_id.c_str());
    }
  }
}

void PrintJson(const CheckReport& report) {
  nlohmann::ordered_json files = nlohmann::ordered_json::array();
  for (const FileReport& file : report.files) {
    if (file.role == FileRole::kInput) continue;
    nlohmann::ordered_json parts = nlohmann::ordered_json::array();
    for (const DecisionPart& part : file.decision) {
      parts.push_back({{"part", part.part}, {"value", part.value}, {"because", part.because}});
    }
    files.push_back({{"path", PrintableName(file)},
                     {"dialect", file.dialect},
                     {"stage", file.stage},
                     {"harness", file.harness},
                     {"target", file.target},
                     {"decision", std::move(parts)}});
  }
  const nlohmann::ordered_json out{{"version", 1}, {"files", std::move(files)}};
  std::printf("%s\n", out.dump(2, ' ', false, nlohmann::json::error_handler_t::replace).c_str());
}

int RunExplainFile(const ExplainArgs& args) {
  if (std::find(kExplainFormats.begin(), kExplainFormats.end(), args.format) ==
      kExplainFormats.end()) {
    return UsageError(UnknownName("--format", args.format, kExplainFormats));
  }
  driver::CheckOptions options;
  options.explain_only = true;
  SourceManager dialect_sources;  // a --dialect FILE.toml, kept for its diagnostics
  std::optional<model::HarnessDialect> harness;
  if (!ResolveKindOptions({args.dialect, args.stage, args.target}, dialect_sources, options,
                          harness)) {
    return kExitUsage;
  }
  for (const std::string& spec : args.channels) {
    if (!ParseChannel(spec, options.channels)) {
      return UsageError("bad --channel '" + spec + "' (expected N=2d|cube|3d)");
    }
  }
  if (!args.common.empty()) options.common = args.common;
  if (!args.config.empty()) options.config = args.config;
  options.use_config = !args.no_config;
  for (const std::string& path : args.paths) options.paths.emplace_back(path);
  driver::CheckRun run = driver::RunCheck(options);
  for (const std::string& error : run.usage_errors) PrintError(error);
  if (!run.usage_errors.empty() && run.report.files.empty()) return kExitUsage;
  if (run.found_nothing) return UsageError(NothingToDo(args.paths, "explain"));
  SortReport(run.report);
  if (args.format == "json") {
    PrintJson(run.report);
  } else {
    PrintText(run.report);
  }
  return run.usage_errors.empty() ? kExitOk : kExitUsage;
}

}  // namespace

void AddExplainFileCommand(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ExplainArgs>();
  CLI::App* command = app.add_subcommand(
      "explain-file",
      "Print what each file is taken to be (dialect, stage, harness, channels, target) and why");
  command->add_option("paths", args->paths, "Files and directories")->required();
  command->add_option("--format", args->format, "text | json")->capture_default_str();
  command->add_option("--dialect", args->dialect,
                      "shadertoy | webgl1 | webgl2 | a harness dialect name | FILE.toml");
  command->add_option("--stage", args->stage, "vertex | fragment");
  command->add_option("--target", args->target, "webgl1 | webgl2");
  command->add_option("--channel", args->channels, "N=2d|cube|3d (repeatable)");
  command->add_option("--common", args->common, "ShaderToy Common code for every pass");
  command->add_option("--config", args->config, "Use this .shaderport.toml instead of searching");
  command->add_flag("--no-config", args->no_config, "Ignore .shaderport.toml files");
  command->callback([args, &exit_code] { exit_code = RunExplainFile(*args); });
}

}  // namespace shaderport::cli
