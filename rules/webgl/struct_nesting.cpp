// webgl/struct-nesting: structs nested more than four levels deep. The WebGL
// specs ("Maximum Nesting of Structures") cap nesting at 4 and browsers reject
// deeper types; GLSL ES itself sets no limit, so glslang accepts them.
//
//   struct S1 { float f; };   struct S2 { S1 s; };   struct S3 { S2 s; };
//   struct S4 { S3 s; };      struct S5 { S4 s; };   // error: 5 levels
#include <map>
#include <string>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/struct-nesting";
constexpr int kMaxNesting = 4;

// Levels of struct in `struct_id`: 1 for a struct of plain fields.
int NestingOf(const glsl::StructTable& structs, uint32_t struct_id, std::map<uint32_t, int>& memo,
              int guard = 0) {
  if (auto it = memo.find(struct_id); it != memo.end()) return it->second;
  int deepest = 0;
  if (guard < 64) {
    for (const glsl::StructField& field : structs.Get(struct_id).fields) {
      if (field.type.base == glsl::BaseType::kStruct && field.type.struct_id < structs.Size()) {
        deepest = std::max(deepest, NestingOf(structs, field.type.struct_id, memo, guard + 1));
      }
    }
  }
  return memo[struct_id] = deepest + 1;
}

class StructNestingRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "A struct nested more than 4 levels deep (WebGL's limit)",
                                     "struct S5 { S4 s; };  // S4 holds S3 holds S2 holds S1", "",
                                     rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    const glsl::StructTable& structs = context.Model().structs;
    std::map<uint32_t, int> memo;
    for (uint32_t id = 0; id < structs.Size(); ++id) {
      const glsl::StructInfo& info = structs.Get(id);
      if (info.declaration == glsl::kNoNode || info.declaration >= context.Tree().NodeCount()) {
        continue;
      }
      const auto* specifier = context.Tree().NodeAt(info.declaration).As<glsl::StructSpecifier>();
      if (specifier == nullptr) continue;
      const int nesting = NestingOf(structs, id, memo);
      if (nesting <= kMaxNesting) continue;
      const SourceRange where = specifier->name.Empty() ? specifier->range : specifier->name.range;
      webgl::ReportError(context, kId, where,
                         "struct '" + info.name + "' nests " + std::to_string(nesting) +
                             " levels of structs; WebGL allows at most " +
                             std::to_string(kMaxNesting));
    }
  }
};

}  // namespace

const rule::Rule& WebglStructNestingRule() {
  static const StructNestingRule rule;
  return rule;
}

}  // namespace shaderport::rules
