// Suppression comments, like clang-tidy's NOLINT: `// shaderport-ignore(rule/id)`
// silences those rules on its own line, `// shaderport-ignore-next-line(rule/id)`
// on the next one (syntax in suppression_comment.h). Comments are taken from the
// lexer's trivia, so only real comments count, and those in inactive #if groups
// are ignored. A suppression that silences nothing is itself reported.
#pragma once

#include <span>

#include "diag/diagnostic.h"
#include "glsl/lex/lexer.h"
#include "source/source_file.h"

namespace shaderport::driver {

struct SuppressionOptions {
  // Off when not every check ran (e.g. a syntax error stopped the semantic rules):
  // a suppression of a rule that never ran is not evidence of anything.
  bool report_unused = true;
};

// Removes from `diagnostics` those that a comment of `file` silences (diagnostics
// located in other files are kept), then appends suppression/unused,
// suppression/malformed and suppression/unknown-rule warnings. Diagnostics of the
// suppression/ category are never silenced by comments (use .shaderport.toml).
void ApplySuppressions(const SourceFile& file, const glsl::LexedFile& lexed,
                       DiagnosticList& diagnostics,
                       std::span<const SourceRange> inactive_regions = {},
                       const SuppressionOptions& options = {});

}  // namespace shaderport::driver
