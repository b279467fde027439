// `shaderport fix`: applies the safe fixes of the always-on rules, keeping each
// file in its own dialect.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands.h"
#include "driver/port/output_files.h"
#include "driver/port/port_file.h"
#include "driver/port/port_report.h"
#include "port_arguments.h"

namespace shaderport::cli {
namespace {

struct FixArgs {
  std::vector<std::string> paths;
  bool diff = false;
  bool in_place = false;
  std::string output;
  PortArguments port;
};

int RunFix(const FixArgs& args) {
  if (args.paths.size() > 1 && !args.in_place && !args.diff) {
    std::fprintf(stderr, "shaderport fix: several files need --in-place or --diff\n");
    return kExitUsage;
  }
  if (!args.output.empty() && args.paths.size() != 1) {
    std::fprintf(stderr, "shaderport fix: -o takes exactly one input file\n");
    return kExitUsage;
  }
  SourceManager sources;
  driver::PortOptions options;
  options.mode = rule::PortMode::kFix;
  std::optional<rule::HarnessDialect> harness;
  if (!ApplyPortArguments("fix", args.port, options, sources, harness)) return kExitUsage;
  int exit_code = kExitOk;
  std::vector<driver::PortResult> results;
  for (const std::string& path : args.paths) {
    driver::PortResult result = driver::PortFile(path, options, sources);
    if (result.read_failed) {
      exit_code = std::max(exit_code, kExitFindings);
    } else if (args.diff) {
      std::fputs(driver::UnifiedDiff(result.file->Text(), result.text, path).c_str(), stdout);
    } else if (args.in_place) {
      if (result.Changed()) {
        const std::string error = driver::WriteFileAtomically(path, result.text);
        if (!error.empty()) {
          std::fprintf(stderr, "shaderport fix: %s\n", error.c_str());
          exit_code = kExitInternal;
        }
      }
    } else if (!args.output.empty()) {
      const std::string error = driver::WriteFileAtomically(args.output, result.text);
      if (!error.empty()) {
        std::fprintf(stderr, "shaderport fix: %s\n", error.c_str());
        exit_code = kExitInternal;
      }
    } else {
      std::fwrite(result.text.data(), 1, result.text.size(), stdout);
    }
    results.push_back(std::move(result));
  }
  if (!driver::HasFindings(results)) return exit_code;
  const bool color = ::isatty(STDERR_FILENO) != 0 && std::getenv("NO_COLOR") == nullptr;
  std::fputs(driver::FormatPortFindings(results, sources, color).c_str(), stderr);
  return std::max(exit_code, kExitFindings);
}

}  // namespace

void AddFixCommand(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<FixArgs>();
  CLI::App* command = app.add_subcommand(
      "fix", "Apply safe fixes, keeping each file's dialect (prints the result by default)");
  command->add_option("paths", args->paths, "Shader files")->required();
  auto* diff = command->add_flag("--diff", args->diff, "Print a unified diff instead");
  auto* in_place =
      command->add_flag("--in-place,-i", args->in_place, "Rewrite the files (atomically)");
  auto* output = command->add_option("-o,--output", args->output, "Write the result to this file");
  diff->excludes(in_place)->excludes(output);
  in_place->excludes(output);
  command->add_option("--dialect", args->port.dialect,
                      "shadertoy|webgl1|webgl2, a harness dialect name, or a dialect TOML");
  command->add_option("--channel", args->port.channels, "Sampler type of a channel: N=2d|cube|3d");
  command->add_option("--stage", args->port.stage, "vertex|fragment (default: detected)");
  command->callback([args, &exit_code] { exit_code = RunFix(*args); });
}

}  // namespace shaderport::cli
