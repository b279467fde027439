// `shaderport fix`: applies the safe fixes of the always-on rules, keeping each
// file in its own dialect.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli_errors.h"
#include "commands.h"
#include "driver/port/fix_run.h"
#include "driver/read_input.h"
#include "model/harness_dialect.h"
#include "option_names.h"
#include "port_arguments.h"
#include "port_findings.h"

namespace shaderport::cli {
namespace {

struct FixArgs {
  InputArguments input;
  bool diff = false;
  bool in_place = false;
  std::string output;
  PortArguments port;
  bool stdin_input = false;    // --stdin
  std::string stdin_filename;  // --stdin-filename
  std::string fail_on = "error";
};

driver::FixDestination DestinationOf(const FixArgs& args) {
  if (args.diff) return driver::FixDestination::kDiff;
  if (args.in_place) return driver::FixDestination::kInPlace;
  if (!args.output.empty()) return driver::FixDestination::kFile;
  return driver::FixDestination::kStandardOutput;
}

// Prints what the run gives; the exit code before the findings count.
int PrintRun(const driver::FixRun& run) {
  std::fwrite(run.standard_output.data(), 1, run.standard_output.size(), stdout);
  for (const std::string& error : run.write_errors) PrintError(error);
  if (run.unsettled || !run.write_errors.empty()) return kExitInternal;
  return run.unreadable ? kExitFindings : kExitOk;
}

int RunFix(const FixArgs& args) {
  const std::optional<Severity> fail_on = SeverityFromName(args.fail_on);
  if (!fail_on) return UsageError(UnknownName("--fail-on", args.fail_on, kSeverityNames));
  SourceManager sources;
  driver::FixRunOptions options;
  std::optional<model::HarnessDialect> harness;
  if (!ApplyPortArguments(args.port, options.port, sources, harness)) return kExitUsage;
  if (!args.stdin_filename.empty() && !args.stdin_input) {
    return UsageError("--stdin-filename needs --stdin");
  }
  options.destination = DestinationOf(args);
  options.output = args.output;

  int exit_code = kExitOk;
  driver::FixRun run;
  if (args.stdin_input) {
    if (!args.input.paths.empty()) return UsageError("--stdin takes no files or directories");
    if (args.in_place) return UsageError("standard input cannot be fixed in place");
    const std::filesystem::path name =
        args.stdin_filename.empty() ? "<stdin>" : args.stdin_filename;
    if (!args.stdin_filename.empty() && ExcludedByConfig(args.input, name)) {
      // Excluded as a named file would be: the text goes back unchanged (ruff).
      const std::string text{std::istreambuf_iterator<char>(std::cin), {}};
      return PrintRun(driver::ReturnUnchanged(text, options));
    }
    run = driver::RunFixOnText(name, driver::ReadInputStream(std::cin), options, sources);
    exit_code = PrintRun(run);
  } else {
    bool config_failed = false;
    const auto inputs = SelectInputFiles(args.input, "fix", config_failed);
    if (!inputs) return kExitUsage;
    if (!args.output.empty() && inputs->size() != 1) {
      return UsageError("-o takes exactly one input file, and the paths hold " +
                        std::to_string(inputs->size()));
    }
    if (inputs->size() > 1 && !args.in_place && !args.diff) {
      return UsageError("the paths hold " + std::to_string(inputs->size()) +
                        " files: fix prints one file; use --in-place or --diff for several");
    }
    run = driver::RunFix(*inputs, options, sources);
    exit_code = std::max(PrintRun(run), config_failed ? kExitFindings : kExitOk);
  }
  return PrintPortFindings(run.results, sources, {}, exit_code, *fail_on);
}

}  // namespace

void AddFixCommand(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<FixArgs>();
  CLI::App* command = app.add_subcommand(
      "fix", "Apply safe fixes, keeping each file's dialect (prints the result by default)");
  AddInputOptions(*command, args->input);
  auto* diff =
      command->add_flag("--diff", args->diff, "Print a unified diff of every file instead");
  auto* in_place =
      command->add_flag("--in-place,-i", args->in_place,
                        "Rewrite the files (atomically, locked against concurrent fix -i)");
  auto* output = command->add_option("-o,--output", args->output, "Write the result to this file");
  diff->excludes(in_place)->excludes(output);
  in_place->excludes(output);
  command->add_option("--dialect", args->port.dialect,
                      "shadertoy|webgl1|webgl2, a harness dialect name, or a dialect TOML");
  command
      ->add_option("--channel", args->port.channels,
                   "Sampler type of a channel: N=2d|cube|3d (repeatable)")
      ->allow_extra_args(false);
  command->add_option("--stage", args->port.stage, "vertex|fragment (default: detected)");
  AddFailOnOption(*command, args->fail_on);
  command->add_flag("--stdin", args->stdin_input,
                    "Fix the shader read from standard input (the result goes to standard output)");
  command->add_option("--stdin-filename", args->stdin_filename,
                      "The path the --stdin text stands for: its extension and directory count "
                      "as for a file there (need not exist)");
  command->callback([args, &exit_code] { exit_code = RunFix(*args); });
}

}  // namespace shaderport::cli
