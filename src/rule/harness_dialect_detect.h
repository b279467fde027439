// Which harness a shader was written for, read from the code itself: the entry
// point it defines instead of main(), and the identifiers it uses without
// declaring them (ShaderToy's iTime, the raymarch blog's uv and color).
#pragma once

#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "glsl/sema/semantic_model.h"
#include "glsl/syntax/ast.h"
#include "model/harness_dialect.h"

namespace shaderport::rule {

// What the code declares at file scope and what it uses without a declaration.
struct CodeInterface {
  std::set<std::string, std::less<>> free_identifiers;   // used, declared nowhere
  std::set<std::string, std::less<>> globals;            // file-scope variables, blocks, structs
  std::set<std::string, std::less<>> functions;          // user functions, defined or declared
  std::set<std::string, std::less<>> defined_functions;  // with a body
};

CodeInterface ReadCodeInterface(const glsl::SyntaxTree& tree, const glsl::SemanticModel& model);

struct DialectMatch {
  const model::HarnessDialect* dialect = nullptr;
  int score = 0;
  std::vector<std::string> evidence;  // "defines mainImage", "uses uv undeclared", ...
};

// The candidate the code fits best, if any fits clearly: it defines the dialect's
// entry point without main(), or uses its provided names without declaring them.
// Earlier candidates win ties.
std::optional<DialectMatch> DetectDialect(std::span<const model::HarnessDialect> candidates,
                                          const CodeInterface& code);

// Same, running the front end (lexer, preprocessor, parser, semantic model) on `text`.
std::optional<DialectMatch> DetectDialectInText(std::span<const model::HarnessDialect> candidates,
                                                std::string_view text);

}  // namespace shaderport::rule
