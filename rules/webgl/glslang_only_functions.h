// Function names glslang declares as built-ins that no browser has (measured with
// Debian 12's glslang against Chromium 156, every name of glslang's built-in table
// declared as a function of a shader): a shader may declare them itself, and may not
// call them undeclared.
#pragma once

#include <string_view>

#include "glsl/lex/preprocessor.h"

namespace shaderport::rules::webgl {

// `version`: the code's GLSL ES version; the GLSL ES 1.00 derivatives count only when
// the shader does not enable GL_OES_standard_derivatives (`preprocessed` may be null).
bool IsGlslangOnlyFunction(std::string_view name, int version,
                           const glsl::PreprocessResult* preprocessed);

// Where glslang's built-in comes from, for messages ("GL_INTEL_shader_integer_functions2").
std::string_view GlslangOnlyFunctionOrigin(std::string_view name);

}  // namespace shaderport::rules::webgl
