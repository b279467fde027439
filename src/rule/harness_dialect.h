// A harness dialect: what a shader host (ShaderToy, glslsandbox, The Book of
// Shaders, a blog's harness) provides to the code and how its entry point
// becomes a real main(). Dialects are data: TOML files under rules/dialects/,
// and users pass their own with `--dialect FILE`.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.h"

namespace shaderport::rule {

struct ProvidedVariable {
  std::string name;
  std::string type;         // GLSL spelling: "vec3", "float[4]", "sampler2D"
  std::string storage;      // "uniform" (declared as a uniform when porting) or "local"
                            // (computed in the generated main(), see `init`)
  std::string init;         // for "local": the GLSL expression that computes it
};

struct HarnessDialect {
  std::string name;                        // "shadertoy", "glslsandbox", ...
  std::string description;
  std::vector<ProvidedVariable> provides;  // uniforms and values the harness supplies
  std::vector<std::string> defines;        // e.g. "HW_PERFORMANCE 1"
  // Entry point the user writes ("mainImage"), empty when the user writes main().
  std::string entry_point;
  // The generated main() body when porting; `{entry}` is replaced by entry_point
  // and `{out}` by the declared fragment output's name.
  std::string main_body;
  // Variables the harness reads back as the colour (e.g. "color"), if the code
  // writes a global instead of an out parameter.
  std::string output_variable;
  // Old names the harness still accepts, renamed when porting: {"iGlobalTime", "iTime"}.
  std::vector<std::pair<std::string, std::string>> renames;
  // Detection hints: identifiers whose use suggests this dialect.
  std::vector<std::string> hints;
};

struct DialectLoadResult {
  std::optional<HarnessDialect> dialect;
  DiagnosticList diagnostics;  // errors in the TOML, located in the file
};

}  // namespace shaderport::rule
