// port/texture-functions: the GLSL ES 1.00 texture lookups, which GLSL ES 3.00
// removed, become the overloaded 3.00 functions (table: rules/data/
// webgl2_texture_renames.def). Only calls of the built-in are renamed: a user
// function or variable that happens to be called texture2D is left alone.
//
// Before:                                 After:
//   texture2D(tex, uv)                      texture(tex, uv)
//   textureCube(env, dir)                   texture(env, dir)
//   texture2DLodEXT(tex, uv, 2.0)           textureLod(tex, uv, 2.0)
#include <string_view>

#include "rules/all_rules.h"
#include "rules/port/port_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "port/texture-functions";

struct TextureRename {
  std::string_view from;
  std::string_view to;
};

constexpr TextureRename kRenames[] = {
#define TEXTURE_RENAME(from, to) {#from, #to},
#include "rules/data/webgl2_texture_renames.def"
#undef TEXTURE_RENAME
};

const TextureRename* FindRename(std::string_view name) {
  for (const auto& rename : kRenames) {
    if (rename.from == name) return &rename;
  }
  return nullptr;
}

class TextureFunctionsRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId,
                                     "Rename texture2D, textureCube and friends to texture, "
                                     "textureLod, ...",
                                     "vec4 c = texture2D(tex, uv);", "vec4 c = texture(tex, uv);",
                                     rule::RuleScope::kPort};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    const auto& tree = context.Tree();
    const auto& model = context.Model();
    for (uint32_t id = 0; id < tree.NodeCount(); ++id) {
      const auto* call = tree.NodeAt(id).As<glsl::CallExpr>();
      if (call == nullptr || call->call_kind != glsl::CallKind::kFunction) continue;
      const TextureRename* rename = FindRename(call->callee.text);
      if (rename == nullptr || !IsBuiltinCall(model, id)) continue;
      if (!webgl2::InThisFile(context, call->callee.range)) continue;
      auto diagnostic = webgl2::MakeDiagnostic(kId, Severity::kWarning, call->callee.range,
                                               "'" + call->callee.text +
                                                   "' does not exist in GLSL ES 3.00; use '" +
                                                   std::string(rename->to) + "'");
      diagnostic.fixes.push_back(webgl2::Replace(
          webgl2::NameFixRange(context, *call, call->callee.range, call->callee.text),
          std::string(rename->to)));
      context.Report(std::move(diagnostic));
    }
  }

 private:
  // A call that resolved to a built-in overload, or that names the built-in when
  // overload resolution failed (e.g. an argument of unknown type): never a user
  // function or a variable of that name.
  static bool IsBuiltinCall(const glsl::SemanticModel& model, uint32_t call) {
    if (model.builtin_calls.contains(call)) return true;
    const uint32_t symbol = model.SymbolAt(call);
    if (symbol != glsl::kNoSymbol) {
      return model.symbols[symbol].kind == glsl::SymbolKind::kBuiltinFunction;
    }
    return false;
  }
};

}  // namespace

const rule::Rule& PortTextureFunctionsRule() {
  static const TextureFunctionsRule rule;
  return rule;
}

}  // namespace shaderport::rules
