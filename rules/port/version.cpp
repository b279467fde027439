// port/version: `#version 300 es` on the first line, added or upgraded.
//
// Before:                         After:
//   precision mediump float;        #version 300 es
//   void main() {}                  precision mediump float;
//                                   void main() {}
//
//   #version 100                    #version 300 es
#include "rules/all_rules.h"
#include "rules/port/port_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "port/version";
constexpr std::string_view kDirective = "#version 300 es";

class VersionRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "Declare GLSL ES 3.00 with `#version 300 es`",
                                     "void main() {}", "#version 300 es\nvoid main() {}",
                                     rule::RuleScope::kPort};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    const auto& version = context.Preprocessed().version;
    const FileId file = context.File().Id();
    if (version.present && webgl2::InThisFile(context, version.range)) {
      // ANGLE (so WebGL 2) wants `#version 300 es` on the very first line.
      const bool first_line = context.File().LocationOf(version.range.begin).line == 1;
      if (version.number >= 300 && version.profile == "es" && first_line) return;
      auto diagnostic = webgl2::MakeDiagnostic(kId, Severity::kWarning, version.range,
                                               "'" + std::string(context.TextOf(version.range)) +
                                                   "' becomes '#version 300 es'" +
                                                   (first_line ? "" : " on the first line"));
      if (first_line) {
        diagnostic.fixes.push_back(webgl2::Replace(version.range, std::string(kDirective)));
      } else {
        diagnostic.fixes.push_back(
            webgl2::Replace(webgl2::WholeLines(context.File(), version.range), ""));
        diagnostic.fixes.push_back(webgl2::Insert(file, 0, std::string(kDirective) + "\n"));
      }
      context.Report(std::move(diagnostic));
      return;
    }
    if (version.present) return;  // declared in an earlier part (Common): not ours to move
    // No #version: GLSL ES 1.00. Insert at the very start: only comments and white space
    // may precede #version, and a leading comment may be a licence header worth keeping
    // on top, but putting the directive first is always valid.
    auto diagnostic = webgl2::MakeDiagnostic(kId, Severity::kWarning, {file, 0, 0},
                                             "no #version: the shader is GLSL ES 1.00; add "
                                             "'#version 300 es' on the first line");
    diagnostic.fixes.push_back(webgl2::Insert(file, 0, std::string(kDirective) + "\n"));
    context.Report(std::move(diagnostic));
  }
};

}  // namespace

const rule::Rule& PortVersionRule() {
  static const VersionRule rule;
  return rule;
}

}  // namespace shaderport::rules
