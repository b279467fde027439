// webgl/backslash-at-end: GLSL ES 3.00 code whose last character (blanks aside) is a
// backslash. A backslash continues a line only when a line end follows it; browsers
// reject this one ("'\' : invalid character"), while glslang reads it as a line
// continuation into nothing and accepts the file. (A backslash elsewhere that no
// line end follows is glslang's error already; GLSL ES 1.00 code gets glslang's
// "line continuation" error.)
//
//   void main() {} \<end of file>   // error
#include <string_view>

#include "rules/all_rules.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl/backslash-at-end";

class BackslashAtEndRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "A backslash as the last character of the file",
                                     "void main() {} \\", "", rule::RuleScope::kCheck};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    // ShaderToy passes are followed by the site's own text.
    if (context.Settings().source_version < 300 || context.Settings().behind_site_header) return;
    const auto& tokens = context.Lexed().tokens;
    if (tokens.size() < 2) return;
    const glsl::Token& last = tokens[tokens.size() - 2];
    if (last.kind != glsl::TokenKind::kInvalid || last.text != "\\") return;
    const glsl::Token& end = tokens.back();
    for (uint32_t i = end.trivia_begin; i < end.trivia_end; ++i) {
      if (context.Lexed().trivia[i].kind != glsl::TriviaKind::kWhitespace) return;
    }
    webgl::ReportError(context, kId, {context.File().Id(), last.begin, last.begin + 1},
                       "'\\' : invalid character: a backslash continues a line only when a "
                       "line end follows it, and none does at the end of the file");
  }
};

}  // namespace

const rule::Rule& WebglBackslashAtEndRule() {
  static const BackslashAtEndRule rule;
  return rule;
}

}  // namespace shaderport::rules
