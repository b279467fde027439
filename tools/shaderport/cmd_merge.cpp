#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "base/file_io/atomic_write.h"
#include "base/file_io/read_regular_file.h"
#include "base/limits.h"
#include "cli_errors.h"
#include "commands.h"
#include "driver/port/output_files.h"
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
  if (!args.output.empty()) {
    const std::vector<std::filesystem::path> read(args.files.begin(), args.files.end());
    if (const std::string clash = driver::OutputReplacesInput("-o", args.output, read);
        !clash.empty()) {
      return UsageError(clash);
    }
  }
  std::vector<MergeInput> inputs;
  for (const std::string& name : args.files) {
    file_io::ReadResult read = file_io::ReadRegularFile(name, limits::kMaxReportBytes);
    if (!read.bytes) return UsageError(name + ": " + read.message);
    inputs.push_back({name, std::move(*read.bytes)});
  }
  const MergeResult merged = MergeReports(inputs, format);
  for (const std::string& error : merged.errors) PrintError(error);
  if (!merged.errors.empty()) return kExitUsage;
  if (args.output.empty()) {
    std::fwrite(merged.output.data(), 1, merged.output.size(), stdout);
    if (std::fflush(stdout) != 0) return kExitInternal;
  } else if (const std::string error = file_io::WriteFileAtomically(args.output, merged.output);
             !error.empty()) {
    PrintError(error);
    return kExitInternal;
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
