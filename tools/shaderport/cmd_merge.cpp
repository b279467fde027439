#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_errors.h"
#include "commands.h"
#include "option_names.h"
#include "report/merge.h"

namespace shaderport::cli {
namespace {

struct MergeArgs {
  std::vector<std::string> files;
  std::string format;
  std::string fail_on = "error";
  std::string output;
};

int RunMergeCommand(const MergeArgs& args) {
  std::optional<MergeFormat> format;
  if (args.format == "json") {
    format = MergeFormat::kJson;
  } else if (args.format == "sarif") {
    format = MergeFormat::kSarif;
  } else if (!args.format.empty()) {
    return UsageError(UnknownName("--format", args.format, kMergeFormatNames));
  }
  const std::optional<Severity> fail_on = SeverityFromName(args.fail_on);
  if (!fail_on) return UsageError(UnknownName("--fail-on", args.fail_on, kSeverityNames));
  if (args.files.empty()) return UsageError("no reports to merge");
  std::vector<MergeInput> inputs;
  for (const std::string& name : args.files) {
    std::ifstream in(name, std::ios::binary);
    if (!in) return UsageError(name + ": cannot be read");
    std::ostringstream text;
    text << in.rdbuf();
    inputs.push_back({name, text.str()});
  }
  const MergeResult merged = MergeReports(inputs, format);
  for (const std::string& error : merged.errors) PrintError(error);
  if (!merged.errors.empty()) return kExitUsage;
  if (args.output.empty()) {
    std::fwrite(merged.output.data(), 1, merged.output.size(), stdout);
    if (std::fflush(stdout) != 0) return kExitInternal;
  } else {
    std::ofstream out(args.output, std::ios::binary);
    out << merged.output;
    if (!out.flush()) {
      PrintError("cannot write " + args.output);
      return kExitInternal;
    }
  }
  return merged.worst && *merged.worst >= *fail_on ? kExitFindings : kExitOk;
}

}  // namespace

void AddMergeCommand(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<MergeArgs>();
  auto* command = app.add_subcommand(
      "merge", "Join the JSON or SARIF outputs of several check runs (e.g. --shard) into one");
  command->add_option("files", args->files, "Outputs of `shaderport check --format json|sarif`");
  command->add_option("--format", args->format,
                      "json | sarif: the inputs' format (default: that of the first input)");
  command->add_option("--fail-on", args->fail_on,
                      "Lowest severity that makes the exit code 1: error (default) | warning | "
                      "note");
  command->add_option("-o,--output", args->output, "Write the merged report here, not to stdout");
  command->callback([args, &exit_code] { exit_code = RunMergeCommand(*args); });
}

}  // namespace shaderport::cli
