// Which flavour of GLSL a file is written in, and which stage it is.
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>

#include "model/pass_kind.h"
#include "model/stage.h"
#include "model/target.h"

namespace shaderport::glsl {
struct LexedFile;  // glsl/lex/lexer.h
}  // namespace shaderport::glsl

namespace shaderport::driver {

enum class Dialect { kShaderToy, kWebGL1, kWebGL2 };

std::string_view DialectName(Dialect dialect);  // "shadertoy", "webgl1", "webgl2"
std::optional<Dialect> ParseDialect(std::string_view name);

struct DetectedKind {
  Dialect dialect = Dialect::kWebGL1;
  model::Stage stage = model::Stage::kFragment;
  model::PassKind pass = model::PassKind::kImage;
  // Why, for people (static text): "defines mainImage() and no main()".
  std::string_view dialect_because = "no #version line: GLSL ES 1.00";
  std::string_view stage_because = "the default stage";
};

// Looks at the code itself (comments and inactive text ignored): `#version 300 es`
// means WebGL2; a `mainImage`/`mainCubemap`/`mainSound` and no `main` means
// ShaderToy; otherwise WebGL1 (no #version is GLSL ES 1.00). The stage comes from
// the extension, else from what the code writes (gl_Position means vertex).
DetectedKind DetectKind(std::string_view text, const std::filesystem::path& path);

// The same from the file's tokens (glsl::Lex), when the caller has them.
DetectedKind DetectKind(const glsl::LexedFile& lexed, const std::filesystem::path& path);

}  // namespace shaderport::driver
