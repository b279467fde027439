// The harness dialects shipped in rules/dialects/*.toml, compiled into the binary.
// Every layer that needs a host's names (the ShaderToy site's uniforms above all)
// reads them here, so that the TOML is the only list of them.
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "model/harness_dialect.h"

namespace shaderport::model {

// Every shipped dialect, sorted by name; parsed once (thread-safe). A shipped file
// with errors is left out (a test guards this).
std::span<const HarnessDialect> BuiltinDialects();

// By name or alias ("shadertoy", "raymarch-harness"); nullptr when unknown.
const HarnessDialect* FindBuiltinDialect(std::string_view name);

// rules/dialects/shadertoy.toml: the site's uniforms, channels and entry points.
const HarnessDialect& ShaderToyDialect();

// The site's uniforms other than the channels, in the order it declares them
// (iResolution, iTime, ... iFrameRate); the entry points' own are not included.
std::vector<const ProvidedVariable*> ShaderToySiteUniforms();

}  // namespace shaderport::model
