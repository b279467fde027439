// A fragment shader with inputs (`in vec2 vUv;`) cannot be drawn with the
// built-in full-screen triangle: nothing writes its inputs, and the program
// does not link. This writes a vertex shader that feeds every input a smooth
// value derived from the screen position, so such a shader can be smoke-tested
// on its own.
#pragma once

#include <string>
#include <string_view>

namespace shaderport::driver {

// "" when the fragment shader (a whole GLSL ES 3.00 text) declares no inputs.
std::string FeederVertexShader(std::string_view fragment_text);

}  // namespace shaderport::driver
