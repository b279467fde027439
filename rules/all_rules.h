// Every porting rule's factory, one line each, sorted by rule id.
//
// To add a rule: define `const rule::Rule& FooRule();` in its own file under
// rules/ (namespace shaderport::rules), add ONE line below at its sorted place,
// and ONE line in rules/registry.cpp. Keep both lists sorted by rule id.
#pragma once

#include "rule/rule.h"

namespace shaderport::rules {

// clang-format off
// ---- rule factories (sorted by rule id; one line per rule) ----
const rule::Rule& PortabilityIndexRangeRule();  // portability/index-range
const rule::Rule& PortabilityInfiniteLoopRule();  // portability/infinite-loop
const rule::Rule& PortabilityMissingReturnRule();  // portability/missing-return
const rule::Rule& PortabilityOutputNeverWrittenRule();  // portability/output-never-written
const rule::Rule& PortabilityUninitializedReadRule();  // portability/uninitialized-read
const rule::Rule& ShadertoyChannelTypesRule();  // shadertoy/channel-types
const rule::Rule& ShadertoyGlobalTimeRule();  // shadertoy/global-time
const rule::Rule& ShadertoyMainWrapperRule();  // shadertoy/main-wrapper
const rule::Rule& ShadertoyUniformsRule();  // shadertoy/uniforms
const rule::Rule& TypingFloatIndexRule();  // typing/float-index
const rule::Rule& TypingFloatModuloRule();  // typing/float-modulo
const rule::Rule& TypingIntExpressionForFloatRule();  // typing/int-expression-for-float
const rule::Rule& TypingIntLiteralForFloatRule();  // typing/int-literal-for-float
const rule::Rule& TypingNonConstantGlobalInitializerRule();  // typing/non-constant-global-initializer
const rule::Rule& TypingScalarToVectorRule();  // typing/scalar-to-vector
const rule::Rule& WebglAttributeLocationRule();  // webgl/attribute-location
const rule::Rule& WebglBackslashAtEndRule();  // webgl/backslash-at-end
const rule::Rule& WebglBlockLayoutRule();  // webgl/block-layout
const rule::Rule& WebglCallDepthRule();  // webgl/call-depth
const rule::Rule& WebglConstFromVariableRule();  // webgl/const-from-variable
const rule::Rule& WebglDerivativeInConstantRule();  // webgl/derivative-in-constant
const rule::Rule& WebglExpressionComplexityRule();  // webgl/expression-complexity
const rule::Rule& WebglExtensionPlacementRule();  // webgl/extension-placement
const rule::Rule& WebglExtensionSupportRule();  // webgl/extension-support
const rule::Rule& WebglForbiddenOperatorRule();  // webgl/forbidden-operator
const rule::Rule& WebglFragmentOutputLocationsRule();  // webgl/fragment-output-locations
const rule::Rule& WebglFragDataAndColorRule();  // webgl/frag-data-and-color
const rule::Rule& WebglFunctionAsValueRule();  // webgl/function-as-value
const rule::Rule& WebglGlslangOnlyBuiltinRule();  // webgl/glslang-only-builtin
const rule::Rule& WebglIndexExpressionRule();  // webgl/index-expression
const rule::Rule& WebglInterpolationQualifierRule();  // webgl/interpolation-qualifier
const rule::Rule& WebglInvariantRule();  // webgl/invariant
const rule::Rule& WebglLoopFormRule();  // webgl/loop-form
const rule::Rule& WebglLoopIndexWriteRule();  // webgl/loop-index-write
const rule::Rule& WebglMissingMainRule();  // webgl/missing-main
const rule::Rule& WebglParameterRedefinitionRule();  // webgl/parameter-redefinition
const rule::Rule& WebglRecursionRule();  // webgl/recursion
const rule::Rule& WebglRepeatedLayoutRule();  // webgl/repeated-layout
const rule::Rule& WebglReservedNameRule();  // webgl/reserved-name
const rule::Rule& WebglStructInSignatureRule();  // webgl/struct-in-signature
const rule::Rule& WebglStructNestingRule();  // webgl/struct-nesting
const rule::Rule& WebglSwitchCaseTypeRule();  // webgl/switch-case-type
const rule::Rule& WebglUndefinedFunctionRule();  // webgl/undefined-function
const rule::Rule& WebglVariableSizeRule();  // webgl/variable-size
const rule::Rule& WebglVersionRule();  // webgl/version
const rule::Rule& WebglVoidParameterRule();  // webgl/void-parameter
const rule::Rule& Webgl2ExtensionsRule();  // webgl2/extensions
const rule::Rule& Webgl2FragOutputsRule();  // webgl2/frag-outputs
const rule::Rule& Webgl2InterfaceRule();  // webgl2/interface
const rule::Rule& Webgl2PrecisionRule();  // webgl2/precision
const rule::Rule& Webgl2ReservedNamesRule();  // webgl2/reserved-names
const rule::Rule& Webgl2TextureFunctionsRule();  // webgl2/texture-functions
const rule::Rule& Webgl2VersionRule();  // webgl2/version
// ---- end of rule factories ----
// clang-format on

}  // namespace shaderport::rules
