#include "port_arguments.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "cli_errors.h"
#include "driver/dialect.h"
#include "driver/harness_dialects.h"
#include "driver/input_selection.h"
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

namespace {

driver::InputSelectionOptions SelectionOptions(const InputArguments& arguments) {
  driver::InputSelectionOptions options;
  options.paths.assign(arguments.paths.begin(), arguments.paths.end());
  if (!arguments.config.empty()) options.config = arguments.config;
  options.use_config = !arguments.no_config;
  options.force_exclude = !arguments.no_force_exclude;
  return options;
}

void PrintConfigProblems(std::vector<FileReport> problems, const SourceManager& sources) {
  if (problems.empty()) return;
  CheckReport report;
  report.sources = &sources;
  report.files = std::move(problems);
  SortReport(report);
  ReportOptions options;
  options.color = ::isatty(STDERR_FILENO) != 0 && std::getenv("NO_COLOR") == nullptr;
  options.summary_line = false;
  std::fputs(FormatReport(report, OutputFormat::kText, options).c_str(), stderr);
}

}  // namespace

std::optional<std::vector<driver::InputFile>> SelectInputFiles(const InputArguments& arguments,
                                                               const std::string& verb,
                                                               bool& config_failed) {
  if (arguments.paths.empty()) {
    PrintError("no files or directories given");
    return std::nullopt;
  }
  driver::ConfiguredInputs inputs = driver::SelectConfiguredInputs(SelectionOptions(arguments));
  driver::InputSelection& selection = inputs.selection;
  config_failed = selection.ConfigFailed();
  PrintConfigProblems(std::move(selection.config_problems), *inputs.config_sources);
  if (!arguments.allow_empty) {
    selection.errors.insert(selection.errors.end(), selection.unmatched.begin(),
                            selection.unmatched.end());
  }
  for (const std::string& error : selection.errors) PrintError(error);
  if (!selection.errors.empty()) return std::nullopt;
  if (selection.FoundNothing() && !arguments.allow_empty) {
    PrintError(NothingToDo(arguments.paths, verb));
    return std::nullopt;
  }
  return std::move(selection.files);
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

bool ExcludedByConfig(const InputArguments& arguments, const std::filesystem::path& name) {
  driver::InputSelectionOptions options = SelectionOptions(arguments);
  options.paths.clear();
  options.stdin_name = name;
  return driver::SelectConfiguredInputs(options).selection.dropped > 0;
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
