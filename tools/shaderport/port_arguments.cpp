#include "port_arguments.h"

#include <cstdio>

#include "driver/dialect.h"
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

}  // namespace shaderport::cli
