// webgl/version: the #version lines a WebGL context compiles. WebGL 1 takes GLSL
// ES 1.00 only (`#version 100` or none); WebGL 2 also takes `#version 300 es`.
// Anything else (`#version 120`, `#version 300` without `es`, `#version 310 es`)
// is rejected by browsers, although desktop compilers may accept it.
//
//   #version 300 es     // error in a WebGL 1 context
#include <string>

#include "rules/all_rules.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/version";

class VersionRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{
        kId, "A #version the WebGL context does not compile (only 100, and 300 es in WebGL 2)",
        "#version 300 es  // in a WebGL 1 context", "", rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    const glsl::VersionDirective& version = context.Preprocessed().version;
    if (!version.present || version.range.file != context.File().Id()) return;
    const bool es300 = version.number == 300 && version.profile == "es";
    if (version.number != 100 && !es300) {
      webgl::ReportError(context, kId, version.range,
                         "'#version " + std::to_string(version.number) +
                             (version.profile.empty() ? "" : " " + version.profile) +
                             "' is not a version WebGL compiles; use '#version 100' (or none) "
                             "or, in WebGL 2, '#version 300 es'");
      return;
    }
    if (es300 && webgl::InWebgl1(context)) {
      webgl::ReportError(context, kId, version.range,
                         "GLSL ES 3.00 shaders need a WebGL 2 context; WebGL 1 compiles only "
                         "GLSL ES 1.00",
                         "check with --target webgl2 if the page creates a 'webgl2' context");
    }
  }
};

}  // namespace

const rule::Rule& WebglVersionRule() {
  static const VersionRule rule;
  return rule;
}

}  // namespace shaderport::rules
