// Where glslang rejects what browsers accept: each glslang error below is known to
// be wrong for WebGL and becomes a note or the browser's warning, saying why.
// docs/browser-divergence.md lists every case with the browser behaviour it copies.
#pragma once

#include "diag/diagnostic.h"
#include "glsl/lex/lexer.h"
#include "glsl/lex/preprocessor.h"
#include "glsl/sema/semantic_model.h"
#include "glsl/syntax/ast.h"
#include "source/source_file.h"

namespace shaderport::rules {

struct BrowserContext {
  bool webgl2 = true;
  int version = 100;  // the code's GLSL ES version
  bool vertex = false;
  const SourceFile* file = nullptr;  // the user's file
  const glsl::LexedFile* lexed = nullptr;
  const glsl::SyntaxTree* tree = nullptr;
  const glsl::SemanticModel* model = nullptr;  // nullptr when analysis did not run
  const glsl::PreprocessResult* preprocessed = nullptr;
  bool front_end_errors = false;  // our own front end found errors in the file
};

// Rewrites one glslang diagnostic in place when the browser disagrees with it.
void AlignWithBrowser(const BrowserContext& context, Diagnostic& diagnostic);

}  // namespace shaderport::rules
