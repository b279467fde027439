// Fix-its inside macros. An edit to a #define body changes every expansion of
// the macro, so it is applied only when every expansion asked for the very same
// edit; otherwise the diagnostics keep no fix and get a note saying why.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.h"
#include "glsl/lex/preprocessor.h"

namespace shaderport::rule {

// Where a range sits with respect to macros.
enum class MacroPlacement {
  kNone,     // plain code
  kBody,     // only bytes written inside #define bodies
  kUseSite,  // the text of a macro use or its arguments: editing it changes the expansion
};

MacroPlacement PlacementOf(const glsl::PreprocessResult& preprocessed, const SourceRange& range);

// The name of the macro whose body or use `range` touches; empty when none.
std::string MacroNameAt(const glsl::PreprocessResult& preprocessed, const SourceRange& range);

// Collects the diagnostics whose fixes edit macro bodies during one rule's run,
// then decides which of them may keep their fixes.
class MacroFixAgreement {
 public:
  explicit MacroFixAgreement(const glsl::PreprocessResult& preprocessed)
      : preprocessed_(preprocessed) {}

  void Propose(Diagnostic diagnostic) { pending_.push_back(std::move(diagnostic)); }
  bool Empty() const { return pending_.empty(); }

  // Returns the pending diagnostics: fixes kept where every expansion of the
  // edited body tokens proposed the same edit, else dropped with a note.
  DiagnosticList Resolve();

 private:
  // How many times the body token at `offset` was expanded.
  size_t ExpansionCount(const SourceRange& fix_range) const;

  const glsl::PreprocessResult& preprocessed_;
  DiagnosticList pending_;
};

}  // namespace shaderport::rule
