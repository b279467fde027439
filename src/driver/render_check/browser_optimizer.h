// The optimiser Chromium runs on every WebGL shader, run on the text a render hands
// Mesa. SwiftShader (Chromium without a GPU) passes ANGLE's SPIR-V through spirv-opt's
// performance passes (-O), whose folding rules regroup float arithmetic: (x * c1) * c2
// becomes x * (c1 * c2), a * b + a * c becomes a * (b + c), x / c becomes x * (1 / c).
// Each changes the last bit, which hash noise and escape-time fractals turn into
// another colour. `render --browser-optimiser` therefore passes its text through glslang,
// spirv-opt -O and SPIRV-Cross back to ESSL 3.00, and Mesa keeps the result's arithmetic
// as written (the outputs and branch conditions made invariant by the browser
// semantics, source_order_arithmetic). Not the default: Debian's spirv-opt is older than
// Chromium's and regroups differently in places (docs/render.md).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace shaderport::driver {

// The fragment shader `text` (ESSL 3.00, as the browser semantics wrote it) after
// spirv-opt -O, as ESSL 3.00; nullopt when any step fails (the caller then renders
// `text` itself).
std::optional<std::string> OptimizeAsBrowser(std::string_view text);

}  // namespace shaderport::driver
