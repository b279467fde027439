// portability/output-never-written: a GLSL ES 3.00 shader declares an `out` variable
// that nothing in the shader writes (no assignment, ++/--, or out/inout argument).
// A fragment output never written holds an undefined value on every pixel (what a
// browser shows differs by GPU and driver); a vertex output never written feeds the
// fragment shader an undefined value. This is the finding `render` makes from the
// picture (render/unwritten-pixels), made without drawing:
//
//   out vec4 color;
//   void main() { vec4 c = vec4(1.0); }   // 'color' is never written
//
// ShaderToy's mainImage writes its out parameter instead (portability/uninitialized-read).
#include <set>
#include <string>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/portability/portability_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "portability/output-never-written";

class OutputNeverWrittenRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{
        kId, "An out variable of a GLSL ES 3.00 shader that nothing writes",
        "#version 300 es\nprecision highp float;\nout vec4 color;\nvoid main() {}", "(unchanged)",
        rule::RuleScope::kLint};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    const glsl::TranslationUnit* root = context.Tree().Root();
    const glsl::SemanticModel& model = context.Model();
    if (root == nullptr || model.version < 300 || !DefinesMain(*root)) return;
    std::set<uint32_t> written;
    portability::ForEachWrittenExpr(context, *root, [&](const glsl::Expr& target) {
      const glsl::IdentifierExpr* name = portability::ChainRoot(&target);
      if (name == nullptr) return;
      const uint32_t symbol = model.SymbolAt(name->id);
      // An unresolved target may be anything: treat every output as written.
      written.insert(symbol);
    });
    if (written.contains(glsl::kNoSymbol)) return;
    const bool vertex = context.Settings().stage == model::Stage::kVertex;
    for (const glsl::Node* node : root->declarations) {
      const auto* declaration = node != nullptr ? node->As<glsl::VariableDeclaration>() : nullptr;
      if (declaration == nullptr || !declaration->qualifiers.Has(glsl::QualifierKind::kOut)) {
        continue;
      }
      for (const glsl::Declarator* declarator : declaration->declarators) {
        if (declarator == nullptr || declarator->name.Empty()) continue;
        const uint32_t symbol = model.SymbolAt(declarator->id);
        if (symbol == glsl::kNoSymbol || written.contains(symbol)) continue;
        context.Report(
            MakeDiagnostic(Severity::kWarning, std::string(kId), declarator->name.range,
                           "the output '" + declarator->name.text + "' is never written: " +
                               (vertex ? "the fragment shader reads an undefined value from it"
                                       : "every pixel it colours is undefined (black, noise or old "
                                         "contents, depending on the GPU)")));
      }
    }
  }

 private:
  static bool DefinesMain(const glsl::TranslationUnit& root) {
    for (const glsl::Node* node : root.declarations) {
      const auto* function = node != nullptr ? node->As<glsl::FunctionDeclaration>() : nullptr;
      if (function != nullptr && function->body != nullptr && function->name.text == "main") {
        return true;
      }
    }
    return false;
  }
};

}  // namespace

const rule::Rule& PortabilityOutputNeverWrittenRule() {
  static const OutputNeverWrittenRule rule;
  return rule;
}

}  // namespace shaderport::rules
