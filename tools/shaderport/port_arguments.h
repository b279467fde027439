// The options `fix` and `port` share: --dialect, --channel and --stage, and the
// paths they take, walked as `check` walks them.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "driver/input_files.h"
#include "driver/port/port_file.h"
#include "rule/harness_dialect.h"
#include "source/source_manager.h"

namespace shaderport::cli {

struct PortArguments {
  std::string dialect;                // shadertoy | webgl1 | webgl2 | a dialect name | FILE.toml
  std::vector<std::string> channels;  // N=2d|cube|3d
  std::string stage;                  // vertex | fragment
};

// Fills `options`; a loaded dialect lives in `harness`. Prints why and returns
// false on a bad value (a usage error).
bool ApplyPortArguments(const char* command, const PortArguments& arguments,
                        driver::PortOptions& options, SourceManager& sources,
                        std::optional<rule::HarnessDialect>& harness);

// The files named by `paths` (directories walked for shader extensions, hidden
// directories skipped, the include/exclude globs of each file's .shaderport.toml
// applied to the files found in directories, as `check` does). Missing paths are
// printed as usage errors and yield nullopt (exit 2, nothing done). Problems of a
// config file are printed; `config_failed` is set when one is an error.
struct InputArguments {
  std::vector<std::string> paths;
  std::string config;  // --config FILE: instead of searching upward
  bool no_config = false;
};
std::optional<std::vector<driver::InputFile>> SelectInputFiles(const char* command,
                                                               const InputArguments& arguments,
                                                               bool& config_failed);

// Registers the paths, --config and --no-config on `command`.
void AddInputOptions(CLI::App& command, InputArguments& arguments);

}  // namespace shaderport::cli
