// `shaderport fix`: applies the safe fixes of the always-on rules, keeping each
// file in its own dialect.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli_errors.h"
#include "commands.h"
#include "driver/check_projects.h"
#include "driver/port/file_lock.h"
#include "driver/port/output_files.h"
#include "driver/port/port_file.h"
#include "driver/port/port_report.h"
#include "driver/project/fix_document.h"
#include "driver/read_input.h"
#include "option_names.h"
#include "port_arguments.h"

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

int WriteOrReport(const std::filesystem::path& path, const std::string& text) {
  const std::string error = file_io::WriteFileAtomically(path, text);
  if (error.empty()) return kExitOk;
  PrintError(error);
  return kExitInternal;
}

// Sends one fixed file where the options say; returns its exit code. A byte order
// mark the input began with is written back: fix changes only what rules fix.
int Emit(const FixArgs& args, const driver::PortResult& result, const std::filesystem::path& path) {
  if (result.read_failed) return kExitFindings;
  // Fixes that did not settle are not written anywhere, not even to standard output:
  // a format-on-save editor keeps its text (the findings name the rules).
  if (!result.converged) return kExitInternal;
  if (args.diff) {
    std::fputs(driver::UnifiedDiff(result.file->Text(), result.text, path.string()).c_str(),
               stdout);
    return kExitOk;
  }
  const std::string text = (result.byte_order_mark ? "\xEF\xBB\xBF" : "") + result.text;
  if (args.in_place) {
    if (result.Changed()) return WriteOrReport(path, text);
  } else if (!args.output.empty()) {
    return WriteOrReport(args.output, text);
  } else {
    std::fwrite(text.data(), 1, text.size(), stdout);
  }
  return kExitOk;
}

// A ShaderToy JSON document: the fixed code goes back into its code strings only.
int EmitDocument(const FixArgs& args, const driver::project::FixedDocument& fixed,
                 const std::filesystem::path& path) {
  if (fixed.read_failed) return kExitFindings;
  if (!driver::AllConverged(fixed.passes)) return kExitInternal;
  driver::PortResult whole;
  whole.file = fixed.document;
  whole.text = fixed.text;
  return Emit(args, whole, path);
}

// The passes' findings, and the document's own problems as a result of their own.
void AddDocumentResults(driver::project::FixedDocument fixed,
                        std::vector<driver::PortResult>& results) {
  if (!fixed.problems.empty()) {
    driver::PortResult problems;
    problems.file = fixed.document;
    problems.read_failed = true;
    problems.diagnostics = std::move(fixed.problems);
    results.push_back(std::move(problems));
  }
  for (driver::PortResult& pass : fixed.passes) results.push_back(std::move(pass));
}

int RunFix(const FixArgs& args) {
  const std::optional<Severity> fail_on = SeverityFromName(args.fail_on);
  if (!fail_on) return UsageError(UnknownName("--fail-on", args.fail_on, kSeverityNames));
  SourceManager sources;
  driver::PortOptions options;
  options.mode = rule::PortMode::kFix;
  std::optional<model::HarnessDialect> harness;
  if (!ApplyPortArguments(args.port, options, sources, harness)) return kExitUsage;
  if (!args.stdin_filename.empty() && !args.stdin_input) {
    return UsageError("--stdin-filename needs --stdin");
  }

  int exit_code = kExitOk;
  std::vector<driver::PortResult> results;
  if (args.stdin_input) {
    if (!args.input.paths.empty()) return UsageError("--stdin takes no files or directories");
    if (args.in_place) return UsageError("standard input cannot be fixed in place");
    const std::filesystem::path name =
        args.stdin_filename.empty() ? "<stdin>" : args.stdin_filename;
    if (!args.stdin_filename.empty() && ExcludedByConfig(args.input, name)) {
      // Excluded as a named file would be: the text goes back unchanged (ruff).
      const std::string text{std::istreambuf_iterator<char>(std::cin), {}};
      if (args.diff) return kExitOk;
      if (!args.output.empty()) return WriteOrReport(args.output, text);
      std::fwrite(text.data(), 1, text.size(), stdout);
      return kExitOk;
    }
    if (driver::IsProjectDocument(name)) {
      driver::project::FixedDocument fixed =
          driver::project::FixDocument(name, driver::ReadInputStream(std::cin), options, sources);
      exit_code = EmitDocument(args, fixed, name);
      AddDocumentResults(std::move(fixed), results);
    } else {
      results.push_back(
          driver::PortInput(name, driver::ReadInputStream(std::cin), options, sources));
      exit_code = Emit(args, results.back(), name);
    }
  } else {
    bool config_failed = false;
    const auto inputs = SelectInputFiles(args.input, "fix", config_failed);
    if (!inputs) return kExitUsage;
    if (config_failed) exit_code = kExitFindings;
    if (!args.output.empty() && inputs->size() != 1) {
      return UsageError("-o takes exactly one input file, and the paths hold " +
                        std::to_string(inputs->size()));
    }
    if (inputs->size() > 1 && !args.in_place && !args.diff) {
      return UsageError("the paths hold " + std::to_string(inputs->size()) +
                        " files: fix prints one file; use --in-place or --diff for several");
    }
    for (const driver::InputFile& input : *inputs) {
      // Held from reading to writing: a concurrent `fix -i` of the same file
      // waits, then reads (and leaves alone) the text written here.
      const driver::FileUpdateLock lock =
          args.in_place ? driver::FileUpdateLock(input.path) : driver::FileUpdateLock();
      if (driver::IsProjectDocument(input.path)) {
        driver::project::FixedDocument fixed = driver::project::FixDocument(
            input.path, driver::ReadInputFile(input.path), options, sources);
        exit_code = std::max(exit_code, EmitDocument(args, fixed, input.path));
        AddDocumentResults(std::move(fixed), results);
        continue;
      }
      results.push_back(driver::PortFile(input.path, OptionsFor(options, input), sources));
      exit_code = std::max(exit_code, Emit(args, results.back(), input.path));
    }
  }
  if (!driver::HasFindings(results)) return exit_code;
  const bool color = ::isatty(STDERR_FILENO) != 0 && std::getenv("NO_COLOR") == nullptr;
  std::fputs(driver::FormatPortFindings(results, sources, color).c_str(), stderr);
  return std::max(exit_code, driver::FailsAt(results, *fail_on) ? kExitFindings : kExitOk);
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
