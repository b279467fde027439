// typing/non-constant-global-initializer: a global whose initializer is not a
// constant expression (browsers accept it, glslang and Mesa reject it) keeps its
// declaration without the initializer, and the assignment becomes the first
// statement of the entry function: main(), or mainImage() for ShaderToy code.
// Only when that computes the same value: no `const`, the initializer reads only
// uniforms, globals and built-ins, and the assignments keep declaration order.
//
// Before:                         After:
//   uniform float time;             uniform float time;
//   float t = time * 2.0;           float t;
//   void main() {                   void main() {
//     gl_FragColor = vec4(t);         t = time * 2.0;
//   }                                 gl_FragColor = vec4(t);
//                                   }
#include "rules/all_rules.h"
#include "rules/typing/global_initializer_check.h"
#include "rules/typing/typing_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "typing/non-constant-global-initializer";

const glsl::FunctionDeclaration* FindDefinition(const glsl::TranslationUnit& unit,
                                                std::string_view name) {
  for (const glsl::Node* node : unit.declarations) {
    const auto* f = node->As<glsl::FunctionDeclaration>();
    if (f != nullptr && f->body != nullptr && f->name.text == name) return f;
  }
  return nullptr;
}

// Where the moved assignments go, and how each line starts.
struct Insertion {
  SourceRange at;
  std::string prefix;  // "\n    " after a `{` that ends its line, else " "
};

std::optional<Insertion> InsertionPoint(const rule::RuleContext& context,
                                        const glsl::CompoundStatement& body) {
  const SourceRange brace = body.range;
  if (!typing::InThisFile(context, brace) || brace.Size() == 0 || context.InMacro(brace)) {
    return std::nullopt;
  }
  const std::string_view text = context.Text();
  const uint32_t after = brace.begin + 1;
  size_t line_end = text.find('\n', after);
  if (line_end == std::string_view::npos) line_end = text.size();
  std::string_view rest = text.substr(after, line_end - after);
  const size_t first = rest.find_first_not_of(" \t\r");
  std::string indent = "    ";
  if (!body.statements.empty() && typing::InThisFile(context, body.statements.front()->range)) {
    const uint32_t begin = body.statements.front()->range.begin;
    const uint32_t line_start = context.File().LineStart(context.File().LocationOf(begin).line);
    std::string_view lead = text.substr(line_start, begin - line_start);
    if (lead.find_first_not_of(" \t") == std::string_view::npos) indent = std::string(lead);
  }
  if (first == std::string_view::npos || rest.substr(first).starts_with("//")) {
    // Keep a trailing comment on the brace's line: insert at its end.
    size_t end = line_end;
    if (end > after && text[end - 1] == '\r') --end;
    return Insertion{{brace.file, static_cast<uint32_t>(end), static_cast<uint32_t>(end)},
                     "\n" + indent};
  }
  return Insertion{{brace.file, after, after}, " "};
}

class NonConstantGlobalInitializerRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{
        kId, "Move non-constant global initializers into the entry function",
        "uniform float time;\nfloat t = time;\nvoid main() { gl_FragColor = vec4(t); }",
        "uniform float time;\nfloat t;\nvoid main() { t = time; gl_FragColor = vec4(t); }",
        rule::RuleScope::kAlways};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    const glsl::TranslationUnit* unit = context.Tree().Root();
    if (unit == nullptr) return;
    const glsl::FunctionDeclaration* entry = FindEntry(context, *unit);
    std::optional<Insertion> insertion;
    if (entry != nullptr) insertion = InsertionPoint(context, *entry->body);
    std::vector<Diagnostic> found;
    bool defer = false;  // a typing fix inside some initializer comes first
    for (const glsl::Node* node : unit->declarations) {
      const auto* declaration = node->As<glsl::VariableDeclaration>();
      if (declaration == nullptr || !Plain(declaration->qualifiers)) continue;
      for (const glsl::Declarator* d : declaration->declarators) {
        if (d->initializer == nullptr || !typing::InThisFile(context, d->range)) continue;
        if (typing::ClassifyInitializer(context, *d->initializer) !=
            typing::Constness::kNotConstant) {
          continue;
        }
        found.push_back(Check(context, *declaration, *d, entry, insertion));
        defer = defer || (!found.back().fixes.empty() &&
                          typing::HasTypingFindings(context, *d->initializer));
      }
    }
    for (Diagnostic& diagnostic : found) {
      if (defer && !diagnostic.fixes.empty()) {
        // Moving now could put this assignment after ones moved in a later round.
        diagnostic.fixes.clear();
        diagnostic.notes.push_back(
            {{}, "moved once the strict-typing fixes in the initializers are applied"});
      }
      context.Report(std::move(diagnostic));
    }
  }

 private:
  // No storage qualifier: uniforms, inputs and outputs cannot be initialized anyway.
  static bool Plain(const glsl::QualifierList& qualifiers) {
    for (const glsl::Qualifier& q : qualifiers.items) {
      if (q.kind != glsl::QualifierKind::kPrecision && q.kind != glsl::QualifierKind::kConst &&
          q.kind != glsl::QualifierKind::kInvariant) {
        return false;
      }
    }
    return true;
  }

  static const glsl::FunctionDeclaration* FindEntry(const rule::RuleContext& context,
                                                    const glsl::TranslationUnit& unit) {
    const model::HarnessDialect* harness = context.Settings().harness;
    if (harness != nullptr) {
      for (const model::EntryPoint& entry : harness->entry_points) {
        if (const auto* f = FindDefinition(unit, entry.function)) return f;
      }
    }
    return FindDefinition(unit, "main");
  }

  static Diagnostic Check(const rule::RuleContext& context,
                          const glsl::VariableDeclaration& declaration, const glsl::Declarator& d,
                          const glsl::FunctionDeclaration* entry,
                          const std::optional<Insertion>& insertion) {
    const glsl::Expr& init = *d.initializer;
    auto diagnostic = typing::MakeDiagnostic(
        kId, Severity::kWarning, init.range,
        "the initializer of global '" + d.name.text +
            "' is not a constant expression; browsers accept it, GLSL ES compilers such as "
            "glslang and Mesa reject it");
    auto not_fixed = [&](const std::string& why) {
      diagnostic.notes.push_back({{}, "not fixed automatically: " + why});
      return diagnostic;
    };
    if (declaration.qualifiers.Has(glsl::QualifierKind::kConst)) {
      return not_fixed("the global is 'const'; remove 'const' or use a constant value");
    }
    if (std::string why = typing::WhyNotMovable(context, init); !why.empty()) return not_fixed(why);
    if (entry == nullptr || !insertion) {
      return not_fixed("no entry function in this file to move it into");
    }
    if (entry->range.file != d.range.file || entry->range.begin < d.range.end) {
      return not_fixed("the entry function comes before the declaration");
    }
    for (const glsl::ParameterDeclaration* p : entry->parameters) {
      if (p->name.text == d.name.text ||
          context.TextOf(init.range).find(p->name.text) != std::string_view::npos) {
        if (!p->name.text.empty()) return not_fixed("a parameter of the entry function hides it");
      }
    }
    const uint32_t from = d.array.empty() ? d.name.range.end : d.array.back().range.end;
    const SourceRange removed{d.range.file, from, init.range.end};
    if (from > init.range.begin || !typing::InThisFile(context, removed) ||
        context.InMacro(removed) || context.InMacro(d.range)) {
      return not_fixed("the declaration is written with macros");
    }
    diagnostic.fixes.push_back({removed, ""});
    diagnostic.fixes.push_back({insertion->at, insertion->prefix + d.name.text + " = " +
                                                   std::string(context.TextOf(init.range)) + ";"});
    return diagnostic;
  }
};

}  // namespace

const rule::Rule& TypingNonConstantGlobalInitializerRule() {
  static const NonConstantGlobalInitializerRule rule;
  return rule;
}

}  // namespace shaderport::rules
