// GLSL definitions of built-in functions as Chromium computes them without a GPU
// (WebGL on ANGLE + SwiftShader, the browser of headless and GPU-less machines):
// the same polynomials, range reductions and operation order, so that llvmpipe
// gives the same bits. See cpu_browser_math.cpp for when they are used.
#pragma once

#include <set>
#include <string>
#include <string_view>

namespace shaderport::glsl {

// Uniform that the transform subtracts from divisors: always 0 (GL zeroes uniforms
// and the renderer leaves `shaderport_` uniforms alone), but unknown to the compiler,
// so Mesa cannot turn `x / 3.0` into `x * (1.0 / 3.0)`, which rounds differently.
inline constexpr std::string_view kOpaqueZeroUniform = "shaderport_zero";

// True for the built-ins this library redefines (sin, pow, dot, mix, ...).
bool HasCpuMathDefinition(std::string_view builtin);

// The helper for built-in `builtin`: "shaderport_" + name.
std::string CpuMathHelperName(std::string_view builtin);

// `text` (GLSL inserted among the user's code, which may `#define x ...`) with every
// identifier other than GLSL keywords and the built-ins helpers use prefixed with
// "shaderport_", and swizzles `.x` .. `.w` written as `[0]` .. `[3]`.
std::string MacroProofHelperText(std::string_view text);

// Definitions (one line, no newline) of the helpers for `builtins` and of every
// helper they call, each for float and vec2..vec4 where GLSL has such overloads,
// preceded by the opaque-zero uniform when `declare_zero` is set. Results always pass
// through the opaque zero; parameters too with `opaque_parameters` (needed unless
// every value reaches an invariant output, see WithOpaqueParameters).
std::string CpuMathDefinitions(const std::set<std::string>& builtins, bool declare_zero,
                               bool opaque_parameters);

}  // namespace shaderport::glsl
