// port/extensions: `#extension` lines for GLSL ES 1.00 extensions that GLSL ES
// 3.00 made core are removed, the whole line with its newline (table:
// rules/data/webgl2_core_extensions.def). Other extensions are kept. Lines in
// #if groups inactive here count too: a browser may define the guard macro.
//
// Before:                                             After:
//   #extension GL_OES_standard_derivatives : enable     (line removed)
//   #extension GL_EXT_shader_texture_lod : enable       (line removed)
#include <string_view>

#include "rules/all_rules.h"
#include "rules/port/port_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "port/extensions";

struct CoreExtension {
  std::string_view name;
  std::string_view what;
};

constexpr CoreExtension kCoreExtensions[] = {
#define CORE_EXTENSION(name, what) {#name, what},
#include "rules/data/webgl2_core_extensions.def"
#undef CORE_EXTENSION
};

const CoreExtension* FindCoreExtension(std::string_view name) {
  for (const auto& extension : kCoreExtensions) {
    if (extension.name == name) return &extension;
  }
  return nullptr;
}

class ExtensionsRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{
        kId, "Remove #extension lines for extensions GLSL ES 3.00 made core",
        "#extension GL_OES_standard_derivatives : enable\nvoid main() {}", "void main() {}",
        rule::RuleScope::kPort};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    for (const auto& directive : webgl2::ExtensionLines(context)) {
      const CoreExtension* core = FindCoreExtension(directive.name);
      if (core == nullptr || !webgl2::InThisFile(context, directive.range)) continue;
      auto diagnostic =
          webgl2::MakeDiagnostic(kId, Severity::kWarning, directive.range,
                                 "'" + directive.name + "' is core in GLSL ES 3.00 (" +
                                     std::string(core->what) + "); its #extension line goes");
      diagnostic.fixes.push_back(
          webgl2::Replace(webgl2::WholeLines(context.File(), directive.range), ""));
      context.Report(std::move(diagnostic));
    }
  }
};

}  // namespace

const rule::Rule& PortExtensionsRule() {
  static const ExtensionsRule rule;
  return rule;
}

}  // namespace shaderport::rules
