#include "diag/rule_catalog.h"

#include <algorithm>
#include <array>

namespace shaderport {
namespace {

// Each area of the code owns one .def file of RULE(id, summary, help) rows.
constexpr auto kUnsorted = std::to_array<RuleDescription>({
#define RULE(id, summary, help) RuleDescription{id, summary, help},
#include "diag/catalog/config.def"
#include "diag/catalog/glslang.def"
#include "diag/catalog/input.def"
#include "diag/catalog/internal.def"
#include "diag/catalog/link.def"
#include "diag/catalog/port.def"
#include "diag/catalog/portability.def"
#include "diag/catalog/preprocessor.def"
#include "diag/catalog/render.def"
#include "diag/catalog/semantic.def"
#include "diag/catalog/shadertoy.def"
#include "diag/catalog/spirv.def"
#include "diag/catalog/syntax.def"
#include "diag/catalog/typing.def"
#include "diag/catalog/webgl.def"
#undef RULE
});

constexpr auto Sorted() {
  auto rules = kUnsorted;
  std::sort(rules.begin(), rules.end(),
            [](const RuleDescription& a, const RuleDescription& b) { return a.id < b.id; });
  return rules;
}

constexpr auto kRules = Sorted();

}  // namespace

std::span<const RuleDescription> RuleCatalog() { return kRules; }

const RuleDescription* FindRule(std::string_view id) {
  auto it =
      std::lower_bound(kRules.begin(), kRules.end(), id,
                       [](const RuleDescription& r, std::string_view key) { return r.id < key; });
  return it != kRules.end() && it->id == id ? &*it : nullptr;
}

}  // namespace shaderport
