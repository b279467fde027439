// webgl/fragment-output-locations: the locations of GLSL ES 3.00 fragment outputs.
// With more than one output, every output needs `layout(location = N)` (WebGL 2 has
// no EXT_blend_func_extended); locations must be below MAX_DRAW_BUFFERS (8 in
// Chromium) and must not overlap. glslang leaves the first and last to the linker.
// ShaderToy's own output (`out vec4` in the site's header) counts: a pass that
// declares another output is rejected on the site.
//
//   out vec4 color;
//   out vec4 normal;   // error: give both a layout(location = N)
#include <optional>
#include <string>
#include <vector>

#include "rules/all_rules.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/fragment-output-locations";
constexpr int64_t kMaxDrawBuffers = 8;

struct Output {
  const glsl::Declarator* declarator;
  std::optional<int64_t> location;
  int64_t slots;
};

std::vector<Output> Outputs(const rule::RuleContext& context) {
  std::vector<Output> outputs;
  for (const glsl::Node* node : context.Tree().Root()->declarations) {
    const auto* declaration = node->As<glsl::VariableDeclaration>();
    if (declaration == nullptr || !declaration->qualifiers.Has(glsl::QualifierKind::kOut)) {
      continue;
    }
    const std::optional<int64_t> location = webgl::LayoutLocation(declaration->qualifiers);
    for (const glsl::Declarator* declarator : declaration->declarators) {
      const glsl::Symbol* symbol = webgl::SymbolOf(context, *declarator);
      const int64_t slots =
          symbol != nullptr && symbol->type.array_size > 0 ? symbol->type.array_size : 1;
      outputs.push_back({declarator, location, slots});
    }
  }
  return outputs;
}

class FragmentOutputLocationsRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{
        kId, "Fragment outputs without locations, beyond MAX_DRAW_BUFFERS or overlapping",
        "out vec4 color;\nout vec4 normal;", "", rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    if (webgl::IsEssl100(context) || !webgl::IsFragment(context)) return;
    const std::vector<Output> outputs = Outputs(context);
    const bool site_output = context.Settings().behind_site_header;
    const size_t count = outputs.size() + (site_output ? 1 : 0);
    for (size_t i = 0; i < outputs.size(); ++i) {
      const Output& output = outputs[i];
      const std::string name = output.declarator->name.text;
      if (site_output) {
        webgl::ReportError(context, kId, output.declarator->name.range,
                           "a ShaderToy pass cannot declare a fragment output of its own ('" +
                               name + "'): write the mainImage parameter",
                           "the site declares its own output before your code, without a "
                           "location, and with more than one output every output needs one");
        continue;
      }
      if (!output.location) {
        if (count > 1) {
          webgl::ReportError(
              context, kId, output.declarator->name.range,
              "'" + name +
                  "' needs a layout(location = N): with more than one fragment output "
                  "every output must have one (WebGL 2 has no EXT_blend_func_extended)");
        }
        continue;
      }
      if (*output.location + output.slots > kMaxDrawBuffers) {
        webgl::ReportError(
            context, kId, output.declarator->name.range,
            "'" + name + "' at location " + std::to_string(*output.location) +
                (output.slots > 1 ? " with " + std::to_string(output.slots) + " elements"
                                  : std::string()) +
                " goes beyond MAX_DRAW_BUFFERS (8)");
        continue;
      }
      for (size_t j = 0; j < i; ++j) {
        const Output& before = outputs[j];
        if (!before.location) continue;
        const bool overlap = *output.location < *before.location + before.slots &&
                             *before.location < *output.location + output.slots;
        if (!overlap) continue;
        webgl::ReportError(
            context, kId, output.declarator->name.range,
            "'" + name + "' overlaps the location of '" + before.declarator->name.text + "'");
        break;
      }
    }
  }
};

}  // namespace

const rule::Rule& WebglFragmentOutputLocationsRule() {
  static const FragmentOutputLocationsRule rule;
  return rule;
}

}  // namespace shaderport::rules
