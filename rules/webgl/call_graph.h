// Who calls whom among the shader's own functions: one entry per function with a
// body, listing its calls of user functions in source order (webgl/recursion,
// webgl/call-depth, webgl/undefined-function).
#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include "glsl/syntax/ast.h"
#include "rule/rule_context.h"

namespace shaderport::rules::webgl {

struct Call {
  uint32_t callee = 0;  // a SymbolKind::kFunction symbol
  const glsl::CallExpr* site = nullptr;
};

using CallGraph = std::map<uint32_t, std::vector<Call>>;  // caller symbol -> its calls

CallGraph BuildCallGraph(const rule::RuleContext& context);

}  // namespace shaderport::rules::webgl
