// Validates shader text with glslang in process and reports glslang's findings
// as shaderport Diagnostics on the user's own files, with columns.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.h"
#include "glsl/lex/lexer.h"
#include "source/source_file.h"
#include "validate/glslang_log.h"
#include "validate/glslang_runner.h"

namespace shaderport::validate {

enum class PartKind { kUser, kGenerated };

// One source string of the translation unit, in order.
struct ShaderPart {
  std::string name;       // for people ("Common", "shadertoy-header"); glslang sees "p<index>"
  std::string_view text;  // for user parts: the whole text of `file`, so offsets match it
  FileId file = kNoFile;  // user parts: the original file; generated: a synthetic file or none
  PartKind kind = PartKind::kUser;
  // A user part's file and tokens when the caller has them already (optional):
  // mapping glslang's messages then neither copies nor re-lexes the text.
  const SourceFile* source = nullptr;
  const glsl::LexedFile* lexed = nullptr;
};

struct ValidationRequest {
  std::vector<ShaderPart> parts;
  model::Stage stage = model::Stage::kFragment;
  int default_version = 100;  // used when no #version: 100 = GLSL ES 1.00 (WebGL1)
  bool link = false;          // link checks that the entry point is defined
  // A ShaderToy entry point ("mainImage") that generated code declares and calls.
  // glslang errors about it inside generated parts are the user's wrong signature.
  std::string entry_point;
  std::string
      entry_point_signature;  // shown in that error, e.g. "void mainImage(out vec4, in vec2)"
  // The user parts' texts are an expansion without macros (their files keep the macros):
  // glslang runs in this process even when those files' macros are unbalanced.
  bool texts_expanded = false;
};

// A glslang message tied back to the request's parts.
struct MappedMessage {
  GlslangMessage message;
  int part = -1;  // index into ValidationRequest::parts, -1 when glslang gave no location
};

struct ValidationResult {
  bool compiled = false;
  bool linked = false;                  // false when linking was not requested
  bool crashed = false;                 // glslang crashed or hung: nothing was validated
  std::vector<MappedMessage> messages;  // everything glslang said, in order
  DiagnosticList diagnostics;

  // glslang's verdict: compiled, linked when asked, and not crashed.
  bool Accepted(bool link_requested) const {
    return !crashed && compiled && (!link_requested || linked);
  }
};

// Thread-safe; never throws for bad input. Every error message becomes a
// Diagnostic: in user parts at glslang's line and the column of the quoted token;
// in generated parts as internal/generated-code (a shaderport bug), except the
// entry-point and unfinished-code cases that the user's code causes.
ValidationResult ValidateWithGlslang(const ValidationRequest& request);

}  // namespace shaderport::validate
