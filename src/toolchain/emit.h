// `shaderport port --emit KIND`: takes a validated WebGL2 (ESSL 3.00) shader on to SPIR-V,
// its disassembly, HLSL, MSL, an ESSL round trip through SPIRV-Cross, or reflection JSON.
// docs/spirv.md describes the route and docs/reflect.schema.json the reflection output.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "diag/diagnostic.h"
#include "model/stage.h"
#include "source/source_file.h"

namespace shaderport::toolchain {

enum class EmitKind { kEssl, kSpirv, kSpvasm, kHlsl, kMsl, kEsslRoundtrip, kReflect };

// "essl", "spirv", "spvasm", "hlsl", "msl", "essl-roundtrip", "reflect"; nullopt otherwise.
std::optional<EmitKind> EmitKindFromName(std::string_view name);
const char* EmitKindName(EmitKind kind);
// File name extension (with the dot) for one output of this kind: ".frag"/".vert" for the ESSL
// kinds, ".spv", ".spvasm", ".hlsl", ".metal", ".json".
std::string EmitExtension(EmitKind kind, model::Stage stage);

struct EmitOptions {
  EmitKind kind = EmitKind::kEssl;
  std::optional<std::string> optimize;  // "O" (performance) or "Os" (size); nullopt: none
  int hlsl_shader_model = 50;           // 30..67, as spirv-cross --shader-model
  int msl_version = 20000;              // major*10000 + minor*100 + patch, as spirv-cross
  bool shadertoy = false;               // reflect: report iChannel0..3 usage
};

struct EmitResult {
  std::string output;          // text, or the raw SPIR-V bytes (little endian) for kSpirv
  bool binary = false;         // true for kSpirv
  size_t words_before = 0;     // SPIR-V words glslang produced (0 for kEssl)
  size_t words_after = 0;      // after the optimiser (== words_before without `optimize`)
  DiagnosticList diagnostics;  // pointing into `file`; output is empty when HasErrors()
};

// `file` holds a whole, glslang-valid WebGL2 shader (what `port` produces). kEssl returns its
// text unchanged. Every other kind compiles it to SPIR-V as 310 es (OpenGL client semantics,
// automatic locations and bindings) and validates the module with SPIRV-Tools. Thread-safe:
// independent calls may run in parallel.
EmitResult Emit(const SourceFile& file, model::Stage stage, const EmitOptions& options);

}  // namespace shaderport::toolchain
