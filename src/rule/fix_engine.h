// The fix engine: analyse, run the rules, apply the chosen safe fixes, and
// repeat on the new text until no rule wants a change. Overlapping fixes wait
// for a later round, so deep nesting can take many rounds; the engine stops
// (internal/error naming the rules) when a text comes back (rules undoing each
// other) or after `max_rounds`, and at once on a text past a resource limit.
// Everything reported is located in the original text.
//
// The engine does not know how to analyse a dialect: the caller passes an
// Analyzer (the driver's front end sees ShaderToy's uniforms, Common code...).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "diag/diagnostic.h"
#include "glsl/lex/lexer.h"
#include "glsl/lex/preprocessor.h"
#include "glsl/sema/semantic_model.h"
#include "glsl/syntax/ast.h"
#include "rule/rule.h"
#include "source/edit.h"
#include "source/source_file.h"

namespace shaderport::rule {

// One analysed text. The pointers stay valid while `owner` lives.
struct AnalyzedShader {
  const glsl::LexedFile* lexed = nullptr;
  const glsl::PreprocessResult* preprocessed = nullptr;
  const glsl::SyntaxTree* tree = nullptr;
  const glsl::SemanticModel* model = nullptr;
  DiagnosticList diagnostics;  // front-end findings (lexer, preprocessor, parser)
  std::shared_ptr<const void> owner;
};

using Analyzer = std::function<AnalyzedShader(const SourceFile& file)>;

// Lex, preprocess, parse and analyse `file` alone as GLSL ES `version` (0: its
// own #version) for `stage`, with `predefined` macros. Enough for plain WebGL code and tests.
AnalyzedShader AnalyzePlain(const SourceFile& file, int version = 0,
                            model::Stage stage = model::Stage::kFragment,
                            std::vector<std::string> predefined = {});

struct FixEngineOptions {
  PortSettings settings;
  std::vector<const Rule*> rules;  // in registry order: earlier rules win overlaps
  Analyzer analyze;                // AnalyzePlain when empty
  int max_rounds = 100;            // as ruff: far above what converging rules need
  bool apply_suggestions = false;
  // Called with each fixable diagnostic (located in the original): false keeps
  // its fixes out, and the diagnostic gets `refused_note`.
  std::function<bool(const Diagnostic&)> allow_fix;
  std::string refused_note = "not applied: the result did not validate";
};

struct FixEngineResult {
  std::string text;          // the fixed text
  SourceMap map;             // text -> original
  DiagnosticList remaining;  // rule findings left in `text`, located in the original
  // Findings whose fixes were applied, located in the original with the fixes that
  // edit the original's own text (a later round's fix of inserted text is dropped).
  DiagnosticList fixed;
  DiagnosticList front_end;  // front-end findings on `text`, located in the original
  int rounds = 0;            // rounds that changed the text
  bool converged = true;     // false: rules cycled or still wanted edits after max_rounds
  // The text reached a resource limit (docs/limits.md): no rule ran on it, `front_end`
  // holds the breach. In the first round `text` is the input unchanged; later (the
  // fixes made the text too large) `converged` is false as well.
  bool limit_breached = false;
};

FixEngineResult RunFixEngine(const SourceFile& original, const FixEngineOptions& options);

// Locates a diagnostic found in an edited text (file id `file`) in the original:
// ranges and notes go through `map`; fixes survive only where they edit copied text.
Diagnostic MapToOriginal(Diagnostic diagnostic, const SourceMap& map, FileId file);

}  // namespace shaderport::rule
