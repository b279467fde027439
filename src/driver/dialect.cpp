#include "driver/dialect.h"

#include <string>
#include <string_view>

#include "glsl/lex/lexer.h"
#include "source/source_file.h"

namespace shaderport::driver {

std::string_view DialectName(Dialect dialect) {
  switch (dialect) {
    case Dialect::kShaderToy:
      return "shadertoy";
    case Dialect::kWebGL1:
      return "webgl1";
    case Dialect::kWebGL2:
      return "webgl2";
  }
  return "webgl1";
}

std::optional<Dialect> ParseDialect(std::string_view name) {
  if (name == "shadertoy") return Dialect::kShaderToy;
  if (name == "webgl1") return Dialect::kWebGL1;
  if (name == "webgl2") return Dialect::kWebGL2;
  return std::nullopt;
}

namespace {

std::optional<model::Stage> StageFromExtension(const std::filesystem::path& path) {
  const std::string extension = path.extension().string();
  if (extension == ".vert" || extension == ".vs" || extension == ".vsh")
    return model::Stage::kVertex;
  if (extension == ".frag" || extension == ".fs" || extension == ".fsh")
    return model::Stage::kFragment;
  return std::nullopt;
}

// What the code says about itself, read from real tokens so that words in
// comments do not count.
// Only the entry points matter for detection: flags instead of a set of every defined
// name (a string and a tree node per function of every file).
struct CodeFacts {
  bool version_300 = false;
  bool version_directive = false;
  // `type name (` at file scope-ish, for each entry point name
  bool defines_main = false;
  bool defines_main_image = false;
  bool defines_main_cubemap = false;
  bool defines_main_sound = false;
  bool writes_gl_position = false;
  bool uses_attribute = false;
};

void NoteDefinedFunction(std::string_view name, CodeFacts& facts) {
  if (name == "main") facts.defines_main = true;
  if (name == "mainImage") facts.defines_main_image = true;
  if (name == "mainCubemap") facts.defines_main_cubemap = true;
  if (name == "mainSound") facts.defines_main_sound = true;
}

CodeFacts ReadFacts(const glsl::LexedFile& lexed) {
  CodeFacts facts;
  const auto& tokens = lexed.tokens;
  for (size_t i = 0; i < tokens.size(); ++i) {
    const glsl::Token& token = tokens[i];
    if (token.kind == glsl::TokenKind::kHash && i + 2 < tokens.size() &&
        tokens[i + 1].text == "version") {
      facts.version_directive = true;
      facts.version_300 = tokens[i + 2].text != "100";
    }
    if (token.kind != glsl::TokenKind::kIdentifier) continue;
    if (token.text == "gl_Position") facts.writes_gl_position = true;
    if (token.text == "attribute") facts.uses_attribute = true;
    // `type name (` is a function declaration or definition.
    if (i > 0 && i + 1 < tokens.size() && tokens[i - 1].kind == glsl::TokenKind::kIdentifier &&
        tokens[i + 1].punct == glsl::Punct::kLeftParen) {
      NoteDefinedFunction(token.text, facts);
    }
  }
  return facts;
}

}  // namespace

DetectedKind DetectKind(std::string_view text, const std::filesystem::path& path) {
  const SourceFile file(0, "<detect>", std::string(text));
  return DetectKind(glsl::Lex(file), path);
}

DetectedKind DetectKind(const glsl::LexedFile& lexed, const std::filesystem::path& path) {
  const CodeFacts facts = ReadFacts(lexed);
  DetectedKind kind;
  const bool has_main = facts.defines_main;
  if (facts.version_300) {
    kind.dialect = Dialect::kWebGL2;
    kind.dialect_because = "#version 300 es";
  } else if (!has_main && !facts.version_directive &&
             (facts.defines_main_image || facts.defines_main_cubemap || facts.defines_main_sound)) {
    kind.dialect = Dialect::kShaderToy;
    kind.dialect_because = "defines mainImage() and no main()";
    if (facts.defines_main_cubemap) {
      kind.pass = model::PassKind::kCube;
      kind.dialect_because = "defines mainCubemap() and no main()";
    }
    if (facts.defines_main_sound) {
      kind.pass = model::PassKind::kSound;
      kind.dialect_because = "defines mainSound() and no main()";
    }
  } else if (!has_main && !facts.version_directive && path.filename() == "common.glsl") {
    kind.dialect = Dialect::kShaderToy;
    kind.pass = model::PassKind::kCommon;
    kind.dialect_because = "named common.glsl, with no main()";
  } else if (facts.version_directive) {
    kind.dialect_because = "#version 100";
  }
  if (auto stage = StageFromExtension(path)) {
    kind.stage = *stage;
    kind.stage_because = "the file name's extension";
  } else if (kind.dialect != Dialect::kShaderToy &&
             (facts.writes_gl_position || facts.uses_attribute)) {
    kind.stage = model::Stage::kVertex;
    kind.stage_because = facts.writes_gl_position ? "writes gl_Position" : "declares an attribute";
  } else if (kind.dialect == Dialect::kShaderToy) {
    kind.stage_because = "ShaderToy passes are fragment shaders";
  } else {
    kind.stage_because = "neither a vertex extension nor gl_Position: a fragment shader";
  }
  return kind;
}

}  // namespace shaderport::driver
