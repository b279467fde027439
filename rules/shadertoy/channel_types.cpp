// shadertoy/channel-types: each iChannelN gets the sampler type its input has:
// `--channel N=2d|cube|3d` when given, else what the code's sampling says (a
// 3-component coordinate means a cube map; sampler3D only when told). The type
// is used by shadertoy/uniforms; this rule explains an inferred cube map, warns
// when the code samples a channel both ways, and fixes a channel the code
// declares itself with a type other than the one it was told.
//
// Before (--channel 1=cube):            After:
//   uniform sampler2D iChannel1;          uniform samplerCube iChannel1;
//   ... texture(iChannel1, dir) ...       ... texture(iChannel1, dir) ...
#include "rules/all_rules.h"
#include "rules/shadertoy/harness_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "shadertoy/channel-types";

Diagnostic Make(Severity severity, const SourceRange& range, std::string message) {
  return MakeDiagnostic(severity, std::string(kId), range, std::move(message));
}

// The type specifier of a file-scope declaration of `name` in this file, if any.
const glsl::TypeSpecifier* DeclaredType(const rule::RuleContext& context, std::string_view name) {
  const auto* root = context.Tree().Root();
  if (root == nullptr) return nullptr;
  for (const glsl::Node* node : root->declarations) {
    const auto* declaration = node == nullptr ? nullptr : node->As<glsl::VariableDeclaration>();
    if (declaration == nullptr || declaration->type == nullptr) continue;
    for (const glsl::Declarator* declarator : declaration->declarators) {
      if (declarator->name.text == name) return declaration->type;
    }
  }
  return nullptr;
}

class ChannelTypesRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId,
                                     "Give each ShaderToy channel the sampler type of its input",
                                     "uniform sampler2D iChannel1; // --channel 1=cube",
                                     "uniform samplerCube iChannel1;", rule::RuleScope::kPort};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    const model::HarnessDialect* dialect = context.Settings().harness;
    if (dialect == nullptr) return;
    const auto channels = harness::ChooseChannels(context, *dialect);
    const auto& tree = context.Tree();
    for (const model::ProvidedVariable& variable : dialect->provides) {
      if (variable.channel < 0 || variable.channel > 3) continue;
      const harness::ChannelChoice& choice = channels[variable.channel];
      const std::string number = std::to_string(variable.channel);
      const glsl::TypeSpecifier* declared = DeclaredType(context, variable.name);
      if (declared != nullptr && choice.told) {
        if (declared->name.text == choice.type ||
            declared->name.range.file != context.File().Id()) {
          continue;
        }
        Diagnostic diagnostic = Make(Severity::kWarning, declared->name.range,
                                     variable.name + " is declared " + declared->name.text +
                                         " but its input is a " + choice.type);
        diagnostic.fixes.push_back(FixIt{declared->name.range, choice.type, FixSafety::kSafe});
        context.Report(std::move(diagnostic));
        continue;
      }
      if (choice.use.Conflicting() && !choice.told) {
        Diagnostic diagnostic = Make(
            Severity::kWarning, tree.NodeAt(choice.use.first_cube).range,
            variable.name + " is sampled with both 2- and 3-component coordinates; declaring it " +
                choice.type + " (choose with --channel " + number + "=2d|cube|3d)");
        diagnostic.notes.push_back(
            {tree.NodeAt(choice.use.first_2d).range, "sampled as a 2D texture here"});
        context.Report(std::move(diagnostic));
      } else if (!choice.told && choice.type == "samplerCube" && declared == nullptr) {
        context.Report(Make(Severity::kNote, tree.NodeAt(choice.use.first_cube).range,
                            variable.name +
                                " is sampled with a 3-component coordinate: declaring it "
                                "samplerCube (a volume texture needs --channel " +
                                number + "=3d)"));
      }
    }
  }
};

}  // namespace

const rule::Rule& ShadertoyChannelTypesRule() {
  static const ChannelTypesRule rule;
  return rule;
}

}  // namespace shaderport::rules
