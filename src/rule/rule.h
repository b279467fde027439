// A porting rule: reads the syntax tree and the types, and reports diagnostics
// whose fix-its are byte-range edits on the original text. Rules never change
// the tree; applying fixes is the fix engine's job (src/rule/fix_engine.h).
//
// Each rule lives in its own file under rules/, with a Before/After example in
// its header comment, and is listed in the sorted registry rules/registry.cpp.
#pragma once

#include <span>
#include <string_view>

#include "rule/rule_context.h"

namespace shaderport::rule {

// When a rule runs.
//  - kPort: only when porting to WebGL2 (`shaderport port`): version, interface,
//    outputs, textures, the ShaderToy wrapper, ...
//  - kAlways: also when fixing a file in its own dialect (`shaderport fix`):
//    strict typing, reserved names in ES 3.00 code, ...
//  - kCheck: only in `shaderport check`: what the WebGL target's compiler (the
//    browser) rejects or warns about beyond glslang. Such rules never fix.
//  - kLint: reported by `shaderport check`, and its safe fixes are applied by
//    `shaderport fix` and `shaderport port`: code that works in browsers only
//    because they define what native targets leave undefined (portability/*).
enum class RuleScope { kPort, kAlways, kCheck, kLint };

struct RuleInfo {
  std::string_view id;       // "category/kebab-name", also listed in src/diag/catalog/*.def
  std::string_view summary;  // one line
  std::string_view before;   // a tiny example input
  std::string_view after;    // what the rule makes of it
  RuleScope scope = RuleScope::kPort;
};

class Rule {
 public:
  virtual ~Rule() = default;
  virtual const RuleInfo& Info() const = 0;
  // Reports through `context`; must not throw and must tolerate broken code
  // (unknown types, error nodes): when unsure, report without a fix, or skip.
  virtual void Run(RuleContext& context) const = 0;
};

}  // namespace shaderport::rule
