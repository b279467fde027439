// GLSL definitions of built-in functions as Chromium computes them without a GPU
// (WebGL on ANGLE + SwiftShader, the browser of headless and GPU-less machines):
// the same polynomials, range reductions and operation order, so that llvmpipe
// gives the same bits. See cpu_browser_math.cpp for when they are used.
#pragma once

#include <set>
#include <span>
#include <string>
#include <string_view>

namespace shaderport::glsl {

// Uniform that the transform subtracts from divisors: always 0 (GL zeroes uniforms
// and the renderer leaves `shaderport_` uniforms alone), but unknown to the compiler,
// so Mesa cannot turn `x / 3.0` into `x * (1.0 / 3.0)`, which rounds differently.
inline constexpr std::string_view kOpaqueZeroUniform = "shaderport_zero";

// `(zero < 0.0 ? if_true : if_false)` written as Mesa compiles it without a branch (its
// front end turns every `?:` into an if/else, which costs the compile more than the
// arithmetic): `mix(if_false, if_true, zero < 0.0)` for float and vecN `type`, `?:` for
// other types. Always `if_false`, but the compiler cannot know.
std::string OpaqueSelect(std::string_view type, std::string_view zero, std::string_view if_false,
                         std::string_view if_true);

// True for the built-ins this library redefines (sin, pow, dot, mix, ...).
bool HasCpuMathDefinition(std::string_view builtin);

// The helper for built-in `builtin`: "shaderport_" + name.
std::string CpuMathHelperName(std::string_view builtin);

// `text` (GLSL inserted among the user's code, which may `#define x ...`) with every
// identifier other than GLSL keywords and the built-ins helpers use prefixed with
// "shaderport_", and swizzles `.x` .. `.w` written with `swizzle_letters` (4 letters
// no macro takes, see SwizzleLettersFreeOfMacros) or, without, as `[0]` .. `[3]`,
// which costs Mesa's compiler more.
std::string MacroProofHelperText(std::string_view text, std::string_view swizzle_letters = {});

// "xyzw", "rgba" or "stpq": the first swizzle set none of whose letters `texts`
// `#define` (anywhere, active or not); empty when each set has one.
std::string_view SwizzleLettersFreeOfMacros(std::span<const std::string_view> texts);

// Definitions (one line, no newline) of the helper overloads in `overloads` and of
// every overload they call, preceded by the opaque-zero uniform when `declare_zero`
// is set or a helper uses it. An overload is "min(vec3,float)"; a bare name ("u2f")
// or a signature no helper has stands for all overloads of that built-in. Results
// always pass through the opaque zero; parameters too with `opaque_parameters`
// (needed unless every value reaches an invariant output, see WithOpaqueParameters).
// Mesa compiles every function given, called or not: unused overloads cost time.
std::string CpuMathDefinitions(const std::set<std::string>& overloads, bool declare_zero,
                               bool opaque_parameters, std::string_view swizzle_letters = {});

}  // namespace shaderport::glsl
