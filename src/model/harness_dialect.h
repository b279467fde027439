// A harness dialect: what a shader host (ShaderToy, glslsandbox, The Book of
// Shaders, a blog's harness) provides to the code and how its entry point
// becomes a real main(). Dialects are data: TOML files under rules/dialects/
// (format in rules/dialects/README.md), and users pass their own with
// `--dialect FILE`.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace shaderport::model {

// How a provided variable is declared when the code is ported to WebGL2.
enum class ProvidedStorage {
  kUniform,  // `uniform vec3 iResolution;`
  kInput,    // `in vec2 uv;` (a varying the harness's vertex shader writes)
  kOutput,   // `out vec4 color;` (the harness reads it as the colour)
};

struct ProvidedVariable {
  std::string name;
  std::string type;  // GLSL spelling, optionally with one array size: "vec3", "float[4]"
  ProvidedStorage storage = ProvidedStorage::kUniform;
  std::string precision;      // "", "lowp", "mediump" or "highp"
  int channel = -1;           // 0..3 for a texture channel whose sampler type the port chooses
  std::string description{};  // what the host feeds it, for people (editor hover)
  // Also declared when the host compiles shared code on its own (ShaderToy's Common tab).
  bool in_common_tab = false;
};

// One function the user writes instead of main(), and the main() that calls it.
struct EntryPoint {
  std::string function;  // "mainImage"
  // Body of the generated main(), one statement a line. Placeholders: `{entry}` is
  // the function, `{out}` the generated output variable, `{fresh:NAME}` a local
  // named NAME, or NAME_1, NAME_2... when the code already uses NAME.
  std::string main_body;
  // The same for the host's off-screen buffer passes, when they differ (ShaderToy's
  // Buffer passes keep alpha, which the Image pass forces to 1); empty: main_body.
  std::string buffer_main_body;
  std::string output_name = "fragColor";  // base name of the generated `out highp vec4`
  // Extra variables this entry point's harness provides (e.g. mainCubemap's unCorners).
  std::vector<ProvidedVariable> provides;
};

// Which provided variables a port declares.
enum class DeclareMode {
  kAll,   // every one, as the host does (ShaderToy: redeclaring one is an error there)
  kUsed,  // only those the code uses and does not declare itself (glslsandbox code
          // usually declares `uniform float time;` itself)
};

struct HarnessDialect {
  std::string name;                  // "shadertoy", "glslsandbox", ...
  std::vector<std::string> aliases;  // other names accepted by --dialect
  std::string description;
  DeclareMode declare = DeclareMode::kUsed;
  std::vector<ProvidedVariable> provides;  // uniforms and values the harness supplies
  std::vector<std::string> defines;        // "HW_PERFORMANCE 1": `#define` lines it adds
  // Functions the user may write instead of main(), in preference order. Empty when
  // the user writes main() (glslsandbox, raymarch blog).
  std::vector<EntryPoint> entry_points;
  // Old names the harness still accepts, renamed when porting: {"iGlobalTime", "iTime"}.
  std::vector<std::pair<std::string, std::string>> renames;
  // Detection hints: identifiers whose use suggests this dialect beyond `provides`.
  std::vector<std::string> hints;
  // Lines the host puts before the code when it compiles it ("#version 300 es" and a
  // default precision for the raymarch blog); `check` compiles the code behind them.
  std::string prelude;

  // The GLSL version the prelude's `#version` line sets: 100, 300, or 0 for none.
  int PreludeVersion() const;

  bool NameMatches(std::string_view name_or_alias) const;
  const ProvidedVariable* FindProvided(std::string_view variable) const;
  const EntryPoint* FindEntryPoint(std::string_view function) const;
};

// A problem in a dialect's TOML, at a byte range of its text. The model sits below
// the diagnostics layer, so the caller that owns the file makes it a Diagnostic.
struct DialectProblem {
  bool error = true;    // false: a warning (an unknown key, which is ignored)
  std::string rule_id;  // "dialect/syntax-error", "dialect/invalid-value", ...
  uint32_t begin = 0;
  uint32_t end = 0;
  std::string message;
};

struct DialectParse {
  std::optional<HarnessDialect> dialect;  // absent when the text has errors
  std::vector<DialectProblem> problems;   // in text order
};

// Parses a dialect from TOML text; `name` is the file name toml++ reports. Never throws.
DialectParse ParseDialect(std::string_view text, std::string_view name);

// How DeclarationOf spells a variable without a precision in the dialect.
enum class PrecisionSpelling {
  kExplicit,  // the hosts' default written out: valid beside any default precision statement
  kOmitted,   // left to the default precision statements before it (the site's own header)
};

// `uniform highp vec3 iResolution;`, `in highp vec2 uv;`, `uniform highp float
// iChannelTime[4];`. `type_override` replaces the type (a channel's chosen sampler).
// Without a precision in the dialect, numeric types get highp (the hosts' default:
// ShaderToy says `precision highp float; precision highp int;`), samplers other
// than sampler2D/samplerCube mediump (ShaderToy's sampler3D): the declaration is
// then valid before or after any default precision statement.
std::string DeclarationOf(const ProvidedVariable& variable, std::string_view type_override = {},
                          PrecisionSpelling spelling = PrecisionSpelling::kExplicit);

std::string_view DefaultPrecision(std::string_view type);

// Spellings of ProvidedStorage and DeclareMode in the TOML.
std::string_view StorageName(ProvidedStorage storage);

}  // namespace shaderport::model
