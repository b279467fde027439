// Where glslang rejects what browsers accept: each glslang error below is known to
// be wrong for WebGL and becomes a note or the browser's warning, saying why.
// docs/browser-divergence.md lists every case with the browser behaviour it copies.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "diag/diagnostic.h"
#include "glsl/lex/lexer.h"
#include "glsl/lex/preprocessor.h"
#include "glsl/sema/semantic_model.h"
#include "glsl/syntax/ast.h"
#include "model/stage.h"
#include "model/target.h"
#include "model/webgl_extensions.h"
#include "source/source_file.h"

namespace shaderport::rules {

struct BrowserContext {
  model::Target target = model::Target::kWebGL2;
  model::EnabledExtensions extensions;  // what the page enabled
  int version = 100;                    // the code's GLSL ES version
  model::Stage stage = model::Stage::kFragment;
  const SourceFile* file = nullptr;  // the user's file
  const glsl::LexedFile* lexed = nullptr;
  const glsl::SyntaxTree* tree = nullptr;
  const glsl::SemanticModel* model = nullptr;  // nullptr when analysis did not run
  const glsl::PreprocessResult* preprocessed = nullptr;
  bool front_end_errors = false;  // our own front end found errors in the file
  // Generated code (the site's header) is compiled before the user's parts, so lines
  // glslang needs can go into a generated part of their own (GlslangText::prelude).
  bool behind_header = false;
  // The line each part starts on in the host's one text (ShaderToy), when not 1.
  const std::vector<std::pair<FileId, int64_t>>* first_lines = nullptr;
  // The user's parts compiled together, in order (ShaderToy: Common, then the file).
  std::vector<const SourceFile*> parts;
};

// Rewrites one glslang diagnostic in place when the browser disagrees with it.
void AlignWithBrowser(const BrowserContext& context, Diagnostic& diagnostic);

// The text of `part` (the user's file, or the ShaderToy Common code compiled with it)
// for glslang where glslang and browsers differ on purpose, on the
// same lines (glslang's messages still map to the user's lines): functions that browsers
// let a shader declare under a built-in's name (GLSL ES 1.00: a new overload; GLSL ES
// 3.00: `texture` and a few more) and their calls get a same-length name glslang does
// not know, as do words glslang reserves and browsers do not (`filter`, `shared`...);
// `__FILE__` in GLSL ES 3.00 becomes 0, lines of skipped #if groups are emptied, uses
// `F()` of one-parameter macros (one empty argument in browsers) are expanded in place,
// and `#define` lines that only browsers read are written as glslang reads them.
struct GlslangText {
  std::string text;     // empty when the part needs no change
  std::string prelude;  // lines to compile right before the part (only behind a header)
};
GlslangText TextForGlslang(const BrowserContext& context, const SourceFile& part);

// `part` as our preprocessor expanded it, for glslang when its own preprocessor crashed
// on the part's macros: every token on its line (macro expansions on the line of their
// use), the `#version` and `#extension` lines as written, other directives gone. Lines
// match the part's, so glslang's messages keep their lines (columns are approximate).
std::string ExpandedTextForGlslang(const BrowserContext& context, const SourceFile& part);

}  // namespace shaderport::rules
