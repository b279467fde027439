// Internal to the browser-semantics transforms: the analysed shader they read and
// the collector of the byte edits they make (by file, since a translation unit may
// span a generated header, Common and the pass).
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "glsl/lex/preprocessor.h"
#include "glsl/sema/semantic_model.h"
#include "glsl/syntax/ast.h"
#include "glsl/webgl_semantics/browser_semantics.h"
#include "glsl/webgl_semantics/driver_folding.h"
#include "source/edit.h"

namespace shaderport::glsl {

class EditCollector {
 public:
  explicit EditCollector(const PreprocessResult& preprocessed) : pp_(preprocessed) {}

  // The bytes a node stands for in one file, when edits around it are safe: its
  // tokens are written in the file, or it covers whole macro uses exactly.
  std::optional<SourceRange> Span(const Node& node) const;
  // Offset just after the `{` that opens a compound statement.
  std::optional<SourceRange> AfterOpeningBrace(const CompoundStatement& body) const;
  // Offset of the `}` that closes it.
  std::optional<SourceRange> BeforeClosingBrace(const CompoundStatement& body) const;

  void Insert(FileId file, uint32_t at, std::string text) {
    edits_[file].push_back({at, at, std::move(text)});
  }
  // Before every insertion made so far at the same offset: the opening text of a
  // wrapper around code whose inner parts other transforms have already wrapped.
  void InsertOutermost(FileId file, uint32_t at, std::string text) {
    auto& list = edits_[file];
    list.insert(list.begin(), {at, at, std::move(text)});
  }
  void Replace(const SourceRange& range, std::string text) {
    edits_[range.file].push_back({range.begin, range.end, std::move(text)});
  }
  const std::map<FileId, std::vector<Edit>>& Edits() const { return edits_; }

 private:
  bool StartsExpansion(uint32_t token) const;
  bool EndsExpansion(uint32_t token) const;

  const PreprocessResult& pp_;
  std::map<FileId, std::vector<Edit>> edits_;
};

struct SemanticsContext {
  const SyntaxTree& tree;
  const SemanticModel& model;
  const BrowserSemanticsOptions& options;
  std::vector<uint32_t> parent;  // by node id; kNoNode for the root
  EditCollector& edits;
  BrowserSemanticsResult& result;
  const DriverFolding* folding = nullptr;  // set when math follows Chromium
  std::string_view swizzle_letters;        // for inserted helpers, see MacroProofHelperText

  const Node* Parent(const Node& node) const {
    const uint32_t p = parent[node.id];
    return p == kNoNode ? nullptr : &tree.NodeAt(p);
  }
};

// A constant expression as a browser's compiler folds it: literals, const variables,
// operators, constructors and built-in calls (not texture or derivative ones) on them.
bool IsConstantExpression(const Expr* expr, const SemanticModel& model);
// The walk under both: literals, operators, constructors and foldable built-ins on
// constants, with `identifier` deciding for each name (`depth` grows along the walk)
// and `builtin`, when given, for each built-in call (whose arguments must fold too).
bool IsConstantTree(const Expr* expr, const SemanticModel& model,
                    const std::function<bool(const Expr& identifier, int depth)>& identifier,
                    int depth = 0,
                    const std::function<bool(const CallExpr& call)>& builtin = nullptr);
// True when `node` is inside the body of a function (not in a global initializer).
bool InsideFunctionBody(const SemanticsContext& context, const Node& node);

// The definition of main(), if any.
const FunctionDeclaration* FindMainDefinition(const SyntaxTree& tree);
// The first function definition: where global helper declarations are inserted.
const Node* FirstFunctionDefinition(const SyntaxTree& tree);

// Statements inserted at the start of main() by several transforms, in a fixed order.
struct MainPrologue {
  std::vector<std::string> statements;
};

void ZeroInitializeVariables(SemanticsContext& context, MainPrologue& prologue);
void ClampIndirectIndices(SemanticsContext& context);
void AddRenderProbe(SemanticsContext& context, MainPrologue& prologue);
void RewriteSmoothstepEdges(SemanticsContext& context, const PreprocessResult& preprocessed);
void PromotePrecision(SemanticsContext& context, const PreprocessResult& preprocessed);
void ComputeMathAsCpuBrowser(SemanticsContext& context, const PreprocessResult& preprocessed);
void KeepSourceOrderArithmetic(SemanticsContext& context);
// Makes the value of every branch and loop condition reach the (invariant) render
// probe output `probe`, so that Mesa also keeps in source order what decides control
// flow. Run after every transform that edits inside conditions.
void ExposeBranchConditions(SemanticsContext& context, std::string_view probe);
void AddDefaultReturns(SemanticsContext& context, const PreprocessResult& preprocessed);
void EmptyInactiveLines(std::span<const SourceFile* const> parts,
                        const PreprocessResult& preprocessed, EditCollector& edits);

}  // namespace shaderport::glsl
