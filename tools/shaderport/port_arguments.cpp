#include "port_arguments.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "driver/config/config_lookup.h"
#include "driver/dialect.h"
#include "report/output_format.h"
#include "rules/shadertoy/builtin_dialects.h"

namespace shaderport::cli {
namespace {

bool ParseChannel(const std::string& spec, driver::PortOptions& options) {
  const size_t eq = spec.find('=');
  if (eq != 1 || spec[0] < '0' || spec[0] > '3') return false;
  const std::string kind = spec.substr(2);
  rule::ChannelKind& slot = options.channels[spec[0] - '0'];
  if (kind == "2d") {
    slot = rule::ChannelKind::k2D;
  } else if (kind == "cube") {
    slot = rule::ChannelKind::kCube;
  } else if (kind == "3d") {
    slot = rule::ChannelKind::k3D;
  } else {
    return false;
  }
  return true;
}

// --dialect: a built-in dialect name (shadertoy, webgl1, webgl2) or a TOML file.
bool ResolveDialect(const char* command, const std::string& value, driver::PortOptions& options,
                    SourceManager& sources, std::optional<rule::HarnessDialect>& harness) {
  if (value.empty()) return true;
  if (auto dialect = driver::ParseDialect(value)) {
    options.dialect = dialect;
    return true;
  }
  rule::DialectLoadResult loaded = rules::LoadDialect(value, sources);
  if (!loaded.dialect) {
    for (const Diagnostic& d : loaded.diagnostics) {
      std::fprintf(stderr, "shaderport %s: --dialect %s: %s [%s]\n", command, value.c_str(),
                   d.message.c_str(), d.rule_id.c_str());
    }
    return false;
  }
  if (loaded.dialect->NameMatches("shadertoy")) options.dialect = driver::Dialect::kShaderToy;
  harness = std::move(loaded.dialect);
  options.harness = &*harness;
  return true;
}

}  // namespace

bool ApplyPortArguments(const char* command, const PortArguments& arguments,
                        driver::PortOptions& options, SourceManager& sources,
                        std::optional<rule::HarnessDialect>& harness) {
  if (!ResolveDialect(command, arguments.dialect, options, sources, harness)) return false;
  for (const std::string& spec : arguments.channels) {
    if (!ParseChannel(spec, options)) {
      std::fprintf(stderr, "shaderport %s: bad --channel '%s' (want N=2d|cube|3d)\n", command,
                   spec.c_str());
      return false;
    }
  }
  if (!arguments.stage.empty()) {
    options.stage = driver::ParseStage(arguments.stage);
    if (!options.stage) {
      std::fprintf(stderr, "shaderport %s: bad --stage '%s'\n", command, arguments.stage.c_str());
      return false;
    }
  }
  return true;
}

std::optional<std::vector<driver::InputFile>> SelectInputFiles(const char* command,
                                                               const InputArguments& arguments,
                                                               bool& config_failed) {
  if (arguments.paths.empty()) {
    std::fprintf(stderr, "shaderport %s: error: no files or directories given\n", command);
    return std::nullopt;
  }
  SourceManager config_sources;
  std::optional<std::filesystem::path> explicit_config;
  if (!arguments.config.empty()) explicit_config = arguments.config;
  driver::ConfigLookup configs(!arguments.no_config, explicit_config, config_sources);
  std::vector<std::filesystem::path> paths(arguments.paths.begin(), arguments.paths.end());
  driver::InputSet inputs = driver::WalkInputs(
      paths, [&](const std::filesystem::path& file) { return configs.Includes(file); });
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
  for (const std::string& error : inputs.errors) {
    std::fprintf(stderr, "shaderport %s: error: %s\n", command, error.c_str());
  }
  if (!inputs.errors.empty()) return std::nullopt;
  return std::move(inputs.files);
}

void AddInputOptions(CLI::App& command, InputArguments& arguments) {
  command.add_option("paths", arguments.paths, "Shader files and directories");
  command.add_option("--config", arguments.config,
                     "Use this .shaderport.toml instead of searching");
  command.add_flag("--no-config", arguments.no_config, "Ignore .shaderport.toml files");
}

}  // namespace shaderport::cli
