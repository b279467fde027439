// .shaderport.toml: per-project rule levels, the failure threshold, which files
// `check` looks at and per-glob dialect/stage overrides.
//
//   [rules]
//   "glslang/missing-precision" = "warning"   # off | note | warning | error
//   "suppression/*" = "off"                   # the most specific pattern wins
//   [check]
//   fail-on = "warning"                       # error (default) | warning | note
//   include = ["shaders/**"]
//   exclude = ["third_party/**", "**/*.gen.glsl"]
//   [[files]]
//   glob = "toy/**"
//   dialect = "shadertoy"                     # shadertoy | webgl1 | webgl2
//   stage = "fragment"                        # vertex | fragment
//   target = "webgl1"                         # webgl1 | webgl2
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.h"
#include "driver/dialect.h"
#include "source/source_file.h"
#include "source/source_manager.h"

namespace shaderport::driver {

inline constexpr std::string_view kConfigFileName = ".shaderport.toml";

enum class RuleLevel { kOff, kNote, kWarning, kError };

struct RuleSetting {
  std::string pattern;  // "category/name", "category/*" or "*"
  RuleLevel level = RuleLevel::kError;
};

struct FileOverride {
  std::string glob;
  std::optional<Dialect> dialect;
  std::optional<model::Stage> stage;
  std::optional<model::Target> target;
};

struct Config {
  std::filesystem::path directory;  // globs are relative to it
  std::vector<RuleSetting> rules;
  Severity fail_on = Severity::kError;
  std::vector<std::string> include;  // empty: every file
  std::vector<std::string> exclude;
  std::vector<FileOverride> files;
};

struct ConfigResult {
  Config config;  // what could be read; bad entries are left out
  DiagnosticList diagnostics;
};

// Parses `file` (its name is the config's path). Syntax errors, unknown keys and
// bad values are diagnostics pointing into `file`; the rest of the file still counts.
ConfigResult ParseConfig(const SourceFile& file);
// Adds the text to `sources` as `path` (so diagnostics can show it) and parses it.
ConfigResult ParseConfig(std::string_view text, std::string_view path, SourceManager& sources);

// The level configured for `rule_id`: the most specific matching pattern wins
// (an exact id, then "category/*", then "*"); among equals, the last one written.
std::optional<RuleLevel> RuleLevelFor(const Config& config, std::string_view rule_id);

// Drops diagnostics whose rule is "off" and sets the severity of the others
// that have a configured level.
void ApplyRuleConfig(const Config& config, DiagnosticList& diagnostics);

// True when some diagnostic is at least as severe as `fail-on`.
bool FailsCheck(const Config& config, const DiagnosticList& diagnostics);

// `file` relative to the config directory with '/' separators; nullopt when the
// file is outside it. Pure path arithmetic: the file system is not touched.
std::optional<std::string> PathInConfig(const Config& config, const std::filesystem::path& file);

// Matched by some include glob (or there are none) and by no exclude glob.
bool IsIncluded(const Config& config, const std::filesystem::path& file);

struct FileSettings {
  std::optional<Dialect> dialect;
  std::optional<model::Stage> stage;
  std::optional<model::Target> target;
};
// Every [[files]] entry whose glob matches, later entries overriding earlier ones.
FileSettings SettingsFor(const Config& config, const std::filesystem::path& file);

std::string_view RuleLevelName(RuleLevel level);
std::optional<RuleLevel> ParseRuleLevel(std::string_view name);

}  // namespace shaderport::driver
