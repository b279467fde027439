#include "port_arguments.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "cli_errors.h"
#include "driver/config/config_lookup.h"
#include "driver/dialect.h"
#include "driver/harness_dialects.h"
#include "empty_input.h"
#include "option_names.h"
#include "report/output_format.h"

namespace shaderport::cli {

std::optional<ChannelSpec> ParseChannelSpec(std::string_view spec) {
  if (spec.size() < 3 || spec[1] != '=' || spec[0] < '0' || spec[0] > '3') return std::nullopt;
  const std::optional<model::ChannelKind> kind = model::ParseChannelKind(spec.substr(2));
  if (!kind) return std::nullopt;
  return ChannelSpec{static_cast<size_t>(spec[0] - '0'), *kind};
}

bool ParseChannel(std::string_view spec, model::GivenChannelKinds& channels) {
  const std::optional<ChannelSpec> parsed = ParseChannelSpec(spec);
  if (!parsed) return false;
  channels[parsed->index] = parsed->kind;
  return true;
}

namespace {

// Every name --dialect takes: the three dialects and the shipped harness dialects.
std::vector<std::string> DialectNames() {
  std::vector<std::string> names(kDialectNames.begin(), kDialectNames.end());
  for (std::string& name : driver::ShippedHarnessDialectNames()) names.push_back(std::move(name));
  // ShaderToy is both a dialect and a harness: named once.
  std::vector<std::string> unique;
  for (std::string& name : names) {
    if (std::find(unique.begin(), unique.end(), name) == unique.end()) unique.push_back(name);
  }
  return unique;
}

}  // namespace

bool ResolveDialectOption(const std::string& value, SourceManager& sources,
                          std::optional<driver::Dialect>& dialect,
                          std::optional<model::HarnessDialect>& harness) {
  if (value.empty()) return true;
  if (auto named = driver::ParseDialect(value)) {
    dialect = named;
    return true;
  }
  // A word that names no dialect is a mistyped name, not a missing file.
  const bool looks_like_file = value.find('/') != std::string::npos || value.ends_with(".toml");
  if (!looks_like_file && !std::filesystem::exists(value)) {
    bool known = false;
    for (const std::string& name : DialectNames()) known = known || name == value;
    if (!known) {
      PrintError(UnknownName("--dialect", value, DialectNames()));
      return false;
    }
  }
  rule::DialectLoadResult loaded = driver::LoadHarnessDialect(value, sources);
  if (!loaded.dialect) {
    for (const Diagnostic& d : loaded.diagnostics) {
      const std::string suggestion =
          d.rule_id == "dialect/not-found" ? DidYouMean(value, DialectNames()) : "";
      PrintError("--dialect " + value + ": " + d.message + " [" + d.rule_id + "]" + suggestion);
    }
    return false;
  }
  if (loaded.dialect->NameMatches("shadertoy")) dialect = driver::Dialect::kShaderToy;
  harness = std::move(loaded.dialect);
  return true;
}

bool ApplyPortArguments(const PortArguments& arguments, driver::PortOptions& options,
                        SourceManager& sources, std::optional<model::HarnessDialect>& harness) {
  if (!ResolveDialectOption(arguments.dialect, sources, options.dialect, harness)) return false;
  if (harness) options.harness = &*harness;
  for (const std::string& spec : arguments.channels) {
    if (!ParseChannel(spec, options.channels)) {
      PrintError("bad --channel '" + spec + "' (expected N=2d|cube|3d, N from 0 to 3)");
      return false;
    }
  }
  if (!arguments.stage.empty()) {
    options.stage = model::ParseStage(arguments.stage);
    if (!options.stage) {
      PrintError(UnknownName("--stage", arguments.stage, kStageNames));
      return false;
    }
  }
  return true;
}

std::optional<std::vector<driver::InputFile>> SelectInputFiles(const InputArguments& arguments,
                                                               const std::string& verb,
                                                               bool& config_failed) {
  if (arguments.paths.empty()) {
    PrintError("no files or directories given");
    return std::nullopt;
  }
  SourceManager config_sources;
  std::optional<std::filesystem::path> explicit_config;
  if (!arguments.config.empty()) explicit_config = arguments.config;
  driver::ConfigLookup configs(!arguments.no_config, explicit_config, config_sources);
  if (!configs.ExplicitConfigError().empty()) {
    PrintError(configs.ExplicitConfigError());
    return std::nullopt;
  }
  std::vector<std::filesystem::path> paths(arguments.paths.begin(), arguments.paths.end());
  driver::InputSet inputs = driver::WalkInputs(
      paths, [&](const std::filesystem::path& file) { return configs.Includes(file); },
      !arguments.no_force_exclude);
  if (!arguments.allow_empty) {
    inputs.errors.insert(inputs.errors.end(), inputs.unmatched.begin(), inputs.unmatched.end());
  }
  CheckReport problems;
  problems.sources = &config_sources;
  problems.files = configs.TakeProblems();
  config_failed = false;
  if (!problems.files.empty()) {
    for (const FileReport& file : problems.files) config_failed |= HasErrors(file.diagnostics);
    SortReport(problems);
    ReportOptions options;
    options.color = ::isatty(STDERR_FILENO) != 0 && std::getenv("NO_COLOR") == nullptr;
    options.summary_line = false;
    std::fputs(FormatReport(problems, OutputFormat::kText, options).c_str(), stderr);
  }
  for (const std::string& error : inputs.errors) PrintError(error);
  if (!inputs.errors.empty()) return std::nullopt;
  for (driver::InputFile& input : inputs.files) {
    if (const driver::Config* config = configs.For(input.path)) {
      const driver::FileSettings settings =
          driver::SettingsFor(*config, std::filesystem::absolute(input.path));
      input.dialect = settings.dialect;
      input.stage = settings.stage;
    }
  }
  if (inputs.files.empty() && inputs.dropped == 0 && !arguments.allow_empty) {
    PrintError(NothingToDo(arguments.paths, verb));
    return std::nullopt;
  }
  return std::move(inputs.files);
}

bool ResolveKindOptions(const KindArguments& arguments, SourceManager& sources,
                        driver::CheckOptions& options,
                        std::optional<model::HarnessDialect>& harness) {
  if (!ResolveDialectOption(arguments.dialect, sources, options.dialect, harness)) return false;
  if (harness && !options.dialect) options.harness = &*harness;
  if (!arguments.stage.empty()) {
    options.stage = model::ParseStage(arguments.stage);
    if (!options.stage) {
      PrintError(UnknownName("--stage", arguments.stage, kStageNames));
      return false;
    }
  }
  if (!arguments.target.empty()) {
    options.target = model::ParseTarget(arguments.target);
    if (!options.target) {
      PrintError(UnknownName("--target", arguments.target, kTargetNames));
      return false;
    }
  }
  return true;
}

driver::PortOptions OptionsFor(const driver::PortOptions& options, const driver::InputFile& input) {
  driver::PortOptions for_input = options;
  if (!for_input.dialect && for_input.harness == nullptr) for_input.dialect = input.dialect;
  if (!for_input.stage) for_input.stage = input.stage;
  return for_input;
}

bool ExcludedByConfig(const InputArguments& arguments, const std::filesystem::path& name) {
  if (arguments.no_force_exclude || arguments.no_config) return false;
  SourceManager config_sources;
  std::optional<std::filesystem::path> explicit_config;
  if (!arguments.config.empty()) explicit_config = arguments.config;
  driver::ConfigLookup configs(true, explicit_config, config_sources);
  return configs.ExplicitConfigError().empty() && !configs.Includes(name);
}

void AddFailOnOption(CLI::App& command, std::string& fail_on) {
  command.add_option("--fail-on", fail_on,
                     "Lowest severity of a remaining finding that fails the run: error (default) "
                     "| warning | note");
}

void AddInputOptions(CLI::App& command, InputArguments& arguments) {
  command.add_option("paths", arguments.paths, "Shader files and directories");
  command.add_option("--config", arguments.config,
                     "Use this .shaderport.toml instead of searching");
  command.add_flag("--no-config", arguments.no_config, "Ignore .shaderport.toml files");
  AddEmptyInputOptions(command, arguments.allow_empty, arguments.no_force_exclude);
}

}  // namespace shaderport::cli
