// The tolerant recursive-descent parser for GLSL ES 1.00 and 3.00, and DumpAst.
#pragma once

#include <string>

#include "diag/diagnostic.h"
#include "glsl/lex/preprocessor.h"
#include "glsl/syntax/ast.h"
#include "source/source_manager.h"

namespace shaderport::glsl {

struct ParseOptions {
  /// 100 (GLSL ES 1.00) or 300 (GLSL ES 3.00): decides keywords and reserved words.
  /// Usually PreprocessResult::version.number; ShaderToy code is 300.
  int version = 100;
};

struct ParseResult {
  SyntaxTree tree;  // always has a root, even for empty or broken input
  DiagnosticList diagnostics;
};

/// Parses the preprocessed tokens. Never fails: syntax errors become
/// diagnostics (rule ids `syntax/...`) and the parse resumes at the next `;`,
/// `}` or declaration start. Recursion is bounded by limits::kBrowserParserStack.
/// The tree copies every name it keeps, so it does not depend on `tokens`.
ParseResult Parse(const PreprocessResult& tokens, const ParseOptions& options);

/// An indented dump, one node a line: kind, key attributes, `line:col-line:col`.
std::string DumpAst(const SyntaxTree& tree, const SourceManager& sources);

}  // namespace shaderport::glsl
