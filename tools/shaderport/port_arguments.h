// The options `fix` and `port` share: --dialect, --channel and --stage, and the
// paths they take, walked as `check` walks them.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "driver/check_options.h"
#include "driver/input_files.h"
#include "driver/port/port_file.h"
#include "model/channel_kind.h"
#include "model/harness_dialect.h"
#include "source/source_manager.h"

namespace shaderport::cli {

struct PortArguments {
  std::string dialect;                // shadertoy | webgl1 | webgl2 | a dialect name | FILE.toml
  std::vector<std::string> channels;  // N=2d|cube|3d
  std::string stage;                  // vertex | fragment
};

// `--channel N=2d|cube|3d` (and render's --channel-type): which channel, which kind.
struct ChannelSpec {
  size_t index = 0;
  model::ChannelKind kind = model::ChannelKind::k2D;
};
std::optional<ChannelSpec> ParseChannelSpec(std::string_view spec);
// check's, explain-file's, fix's and port's --channel: sets that channel in `channels`;
// false on a bad spec.
bool ParseChannel(std::string_view spec, model::GivenChannelKinds& channels);

// --dialect: shadertoy, webgl1 or webgl2 sets `dialect`; a harness dialect's name or
// TOML file is loaded into `harness` (ShaderToy's also sets `dialect`). Prints why and
// returns false on a bad value (a usage error).
bool ResolveDialectOption(const std::string& value, SourceManager& sources,
                          std::optional<driver::Dialect>& dialect,
                          std::optional<model::HarnessDialect>& harness);

// check's and explain-file's --dialect, --stage and --target into `options` (a loaded
// harness dialect lives in `harness`). Prints why and returns false on a bad value.
struct KindArguments {
  const std::string& dialect;
  const std::string& stage;
  const std::string& target;
};
bool ResolveKindOptions(const KindArguments& arguments, SourceManager& sources,
                        driver::CheckOptions& options,
                        std::optional<model::HarnessDialect>& harness);

// Fills `options`; a loaded dialect lives in `harness`. Prints why and returns
// false on a bad value (a usage error).
bool ApplyPortArguments(const PortArguments& arguments, driver::PortOptions& options,
                        SourceManager& sources, std::optional<model::HarnessDialect>& harness);

// The files named by `paths` (directories walked for shader extensions, hidden
// directories skipped, the include/exclude globs of each file's .shaderport.toml
// applied, as `check` does). Missing paths are
// printed as usage errors and yield nullopt (exit 2, nothing done). Problems of a
// config file are printed; `config_failed` is set when one is an error.
struct InputArguments {
  std::vector<std::string> paths;
  std::string config;  // --config FILE: instead of searching upward
  bool no_config = false;
  bool allow_empty = false;       // --allow-empty
  bool no_force_exclude = false;  // --no-force-exclude
};
// Paths that hold no shader file, and globs that matched nothing, are usage
// errors unless --allow-empty (`verb` names the command in the message).
std::optional<std::vector<driver::InputFile>> SelectInputFiles(const InputArguments& arguments,
                                                               const std::string& verb,
                                                               bool& config_failed);

// True when the include/exclude globs of the config that governs `name` (the
// --stdin-filename) leave it out and --no-force-exclude was not given.
bool ExcludedByConfig(const InputArguments& arguments, const std::filesystem::path& name);

// Registers --fail-on: the lowest severity of a remaining finding that makes the
// exit code 1 (default error: warnings no fix can repair do not fail a hook).
void AddFailOnOption(CLI::App& command, std::string& fail_on);

// Registers the paths, --config, --no-config, --allow-empty and --no-force-exclude
// on `command`.
void AddInputOptions(CLI::App& command, InputArguments& arguments);

}  // namespace shaderport::cli
