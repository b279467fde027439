// shadertoy/global-time: names a harness used to provide and has since renamed
// (ShaderToy's `iGlobalTime`, now `iTime`; a dialect's `renames` table) are
// renamed at every use, macro bodies included (every expansion agrees), unless
// the code declares or defines the old name itself. The result is still code for
// the same host, so the rule runs in `fix` too.
//
// Before:                               After:
//   float t = iGlobalTime * 0.5;          float t = iTime * 0.5;
#include "rules/all_rules.h"
#include "rules/shadertoy/harness_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "shadertoy/global-time";

class GlobalTimeRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{kId, "Rename harness names that were renamed (iGlobalTime)",
                                     "float t = iGlobalTime * 0.5;", "float t = iTime * 0.5;",
                                     rule::RuleScope::kAlways};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    const model::HarnessDialect* dialect = context.Settings().harness;
    if (dialect == nullptr || dialect->renames.empty()) return;
    const rule::CodeInterface code = rule::ReadCodeInterface(context.Tree(), context.Model());
    const auto macros = harness::DefinedMacros(context);
    const FileId file = context.File().Id();
    for (const auto& [from, to] : dialect->renames) {
      if (code.globals.contains(from) || code.functions.contains(from) || macros.contains(from)) {
        continue;  // the code provides the old name itself
      }
      Diagnostic diagnostic;
      diagnostic.severity = Severity::kWarning;
      diagnostic.rule_id = std::string(kId);
      diagnostic.message = "'" + from + "' is the old name of '" + to + "'; " + dialect->name +
                           " no longer provides it";
      for (const glsl::Token& token : context.Lexed().tokens) {
        if (token.kind != glsl::TokenKind::kIdentifier || token.text != from) continue;
        const SourceRange range{file, token.begin, token.end};
        if (diagnostic.fixes.empty()) diagnostic.range = range;
        diagnostic.fixes.push_back(FixIt{range, to, FixSafety::kSafe});
      }
      if (diagnostic.fixes.empty()) continue;
      // Every occurrence is renamed, in macro bodies too: all expansions agree.
      context.Report(std::move(diagnostic), /*allow_in_macro=*/true);
    }
  }
};

}  // namespace

const rule::Rule& ShadertoyGlobalTimeRule() {
  static const GlobalTimeRule rule;
  return rule;
}

}  // namespace shaderport::rules
