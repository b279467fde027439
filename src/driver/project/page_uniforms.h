// The page runtime's table of the ShaderToy site's uniforms, written from the
// harness model (rules/dialects/shadertoy.toml) so that the page's script does not
// list them a second time.
#pragma once

#include <string>

namespace shaderport::driver::project {

// A script fragment, put before runtime.js: `spSiteUniforms` (the site's uniforms
// other than the channels, in its order) and `spEntryPointUniforms` (each entry
// point's own, e.g. mainCubemap's unViewport and unCorners).
std::string ShaderToyUniformsScript();

}  // namespace shaderport::driver::project
