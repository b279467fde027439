#include "rules/registry.h"

#include <algorithm>

#include "rules/all_rules.h"

namespace shaderport::rules {
namespace {

std::vector<const rule::Rule*> BuildRegistry() {
  std::vector<const rule::Rule*> list = {
      // clang-format off
      // ---- rules (sorted by rule id; one line per rule: &FooRule(),) ----
      &PortabilityIndexRangeRule(),  // portability/index-range
      &PortabilityInfiniteLoopRule(),  // portability/infinite-loop
      &PortabilityMissingReturnRule(),  // portability/missing-return
      &PortabilityOutputNeverWrittenRule(),  // portability/output-never-written
      &PortabilityUninitializedReadRule(),  // portability/uninitialized-read
      &ShadertoyChannelTypesRule(),  // shadertoy/channel-types
      &ShadertoyGlobalTimeRule(),  // shadertoy/global-time
      &ShadertoyMainWrapperRule(),  // shadertoy/main-wrapper
      &ShadertoyUniformsRule(),  // shadertoy/uniforms
      &TypingFloatIndexRule(),  // typing/float-index
      &TypingFloatModuloRule(),  // typing/float-modulo
      &TypingIntExpressionForFloatRule(),  // typing/int-expression-for-float
      &TypingIntLiteralForFloatRule(),  // typing/int-literal-for-float
      &TypingNonConstantGlobalInitializerRule(),  // typing/non-constant-global-initializer
      &TypingScalarToVectorRule(),  // typing/scalar-to-vector
      &WebglAttributeLocationRule(),  // webgl/attribute-location
      &WebglBackslashAtEndRule(),  // webgl/backslash-at-end
      &WebglBlockLayoutRule(),  // webgl/block-layout
      &WebglCallDepthRule(),  // webgl/call-depth
      &WebglConstFromVariableRule(),  // webgl/const-from-variable
      &WebglDerivativeInConstantRule(),  // webgl/derivative-in-constant
      &WebglExpressionComplexityRule(),  // webgl/expression-complexity
      &WebglExtensionPlacementRule(),  // webgl/extension-placement
      &WebglExtensionSupportRule(),  // webgl/extension-support
      &WebglForbiddenOperatorRule(),  // webgl/forbidden-operator
      &WebglFragmentOutputLocationsRule(),  // webgl/fragment-output-locations
      &WebglFragDataAndColorRule(),  // webgl/frag-data-and-color
      &WebglFunctionAsValueRule(),  // webgl/function-as-value
      &WebglGlslangOnlyBuiltinRule(),  // webgl/glslang-only-builtin
      &WebglIndexExpressionRule(),  // webgl/index-expression
      &WebglInterpolationQualifierRule(),  // webgl/interpolation-qualifier
      &WebglInvariantRule(),  // webgl/invariant
      &WebglLoopFormRule(),  // webgl/loop-form
      &WebglLoopIndexWriteRule(),  // webgl/loop-index-write
      &WebglMissingMainRule(),  // webgl/missing-main
      &WebglParameterRedefinitionRule(),  // webgl/parameter-redefinition
      &WebglRecursionRule(),  // webgl/recursion
      &WebglRepeatedLayoutRule(),  // webgl/repeated-layout
      &WebglReservedNameRule(),  // webgl/reserved-name
      &WebglStructInSignatureRule(),  // webgl/struct-in-signature
      &WebglStructNestingRule(),  // webgl/struct-nesting
      &WebglSwitchCaseTypeRule(),  // webgl/switch-case-type
      &WebglUndefinedFunctionRule(),  // webgl/undefined-function
      &WebglVariableSizeRule(),  // webgl/variable-size
      &WebglVersionRule(),  // webgl/version
      &WebglVoidParameterRule(),  // webgl/void-parameter
      &Webgl2ExtensionsRule(),  // webgl2/extensions
      &Webgl2FragOutputsRule(),  // webgl2/frag-outputs
      &Webgl2InterfaceRule(),  // webgl2/interface
      &Webgl2PrecisionRule(),  // webgl2/precision
      &Webgl2ReservedNamesRule(),  // webgl2/reserved-names
      &Webgl2TextureFunctionsRule(),  // webgl2/texture-functions
      &Webgl2VersionRule(),  // webgl2/version
      // ---- end of rules ----
      // clang-format on
  };
  // Sorting makes the order (and so fix priority) independent of where a
  // concurrent edit put its line.
  std::stable_sort(list.begin(), list.end(), [](const rule::Rule* a, const rule::Rule* b) {
    return a->Info().id < b->Info().id;
  });
  return list;
}

}  // namespace

std::span<const rule::Rule* const> AllRules() {
  static const std::vector<const rule::Rule*> registry = BuildRegistry();
  return registry;
}

std::vector<const rule::Rule*> RulesForMode(rule::PortMode mode) {
  std::vector<const rule::Rule*> selected;
  for (const rule::Rule* r : AllRules()) {
    const rule::RuleScope scope = r->Info().scope;
    if (scope == rule::RuleScope::kCheck) continue;
    const bool every_mode = scope == rule::RuleScope::kAlways || scope == rule::RuleScope::kLint;
    if (mode == rule::PortMode::kPort || every_mode) selected.push_back(r);
  }
  return selected;
}

std::vector<const rule::Rule*> CheckRules() {
  std::vector<const rule::Rule*> selected;
  for (const rule::Rule* r : AllRules()) {
    const rule::RuleScope scope = r->Info().scope;
    if (scope == rule::RuleScope::kCheck || scope == rule::RuleScope::kLint) selected.push_back(r);
  }
  return selected;
}

const rule::Rule* FindRule(std::string_view id) {
  for (const rule::Rule* r : AllRules()) {
    if (r->Info().id == id) return r;
  }
  return nullptr;
}

}  // namespace shaderport::rules
