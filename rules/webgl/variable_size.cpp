// webgl/variable-size: a local or global variable of 64 KiB or more. Browsers reject
// it ("Size of declared private variable exceeds implementation-defined limit"): such
// a variable cannot live in registers and would spill. Measured in Chromium 156: the
// size counts 4 bytes a scalar component, tightly packed (a vec3 is 12 bytes, a mat3
// 36, a struct the sum of its fields), and 65,536 bytes is one too many (float[16383]
// compiles, float[16384] does not), in both GLSL ES versions. glslang accepts it.
//
//   float history[20000];   // error: 80,000 bytes
#include <string>
#include <unordered_set>
#include <vector>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/variable-size";
constexpr uint64_t kLimitBytes = 65536;

// Bytes of `type`, saturating at the limit (struct nesting is bounded by its depth
// limit, and sizes stop growing once they reach the limit).
uint64_t SizeInBytes(const glsl::SemanticModel& model, const glsl::Type& type, int depth = 0) {
  uint64_t element = 0;
  if (type.base == glsl::BaseType::kStruct) {
    if (depth > 16 || type.struct_id >= model.structs.Size()) return 0;
    for (const glsl::StructField& field : model.structs.Get(type.struct_id).fields) {
      element += SizeInBytes(model, field.type, depth + 1);
      if (element >= kLimitBytes) return kLimitBytes;
    }
  } else {
    element = 4ull * type.rows * type.columns;
  }
  const uint64_t count = type.array_size > 0 ? static_cast<uint64_t>(type.array_size) : 1;
  return element * count >= kLimitBytes ? kLimitBytes : element * count;
}

// Declarations that are not variables of the shader's own: struct fields and
// interface block members.
std::unordered_set<const glsl::Node*> FieldsAndMembers(const glsl::SyntaxTree& tree) {
  std::unordered_set<const glsl::Node*> inside;
  glsl::ForEachNodeOf(tree, {glsl::NodeKind::kStructSpecifier, glsl::NodeKind::kInterfaceBlock},
                      [&](const glsl::Node& node) {
                        if (const auto* block = node.As<glsl::InterfaceBlock>()) {
                          inside.insert(block->members.begin(), block->members.end());
                        } else if (const auto* s = node.As<glsl::StructSpecifier>()) {
                          inside.insert(s->fields.begin(), s->fields.end());
                        }
                      });
  return inside;
}

bool IsInterfaceVariable(const glsl::QualifierList& qualifiers) {
  for (const glsl::Qualifier& qualifier : qualifiers.items) {
    switch (qualifier.kind) {
      case glsl::QualifierKind::kUniform:
      case glsl::QualifierKind::kIn:
      case glsl::QualifierKind::kOut:
      case glsl::QualifierKind::kInOut:
      case glsl::QualifierKind::kAttribute:
      case glsl::QualifierKind::kVarying:
        return true;
      default:
        break;
    }
  }
  return false;
}

class VariableSizeRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "A local or global variable of 64 KiB or more",
                                     "float history[20000];", "", rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    const std::unordered_set<const glsl::Node*> skip = FieldsAndMembers(context.Tree());
    glsl::ForEachNodeOf(
        context.Tree(), {glsl::NodeKind::kVariableDeclaration}, [&](const glsl::Node& node) {
          const auto& declaration = *node.As<glsl::VariableDeclaration>();
          if (skip.contains(&node) || IsInterfaceVariable(declaration.qualifiers)) return;
          for (const glsl::Declarator* declarator : declaration.declarators) {
            const glsl::Symbol* symbol = webgl::SymbolOf(context, *declarator);
            if (symbol == nullptr || symbol->kind != glsl::SymbolKind::kVariable) continue;
            if (SizeInBytes(context.Model(), symbol->type) < kLimitBytes) continue;
            webgl::ReportError(context, kId, declarator->name.range,
                               "'" + declarator->name.text +
                                   "' takes 64 KiB or more; browsers reject private variables "
                                   "that large (\"Size of declared private variable exceeds "
                                   "implementation-defined limit\")");
          }
        });
  }
};

}  // namespace

const rule::Rule& WebglVariableSizeRule() {
  static const VariableSizeRule rule;
  return rule;
}

}  // namespace shaderport::rules
