// Tiny rules for engine tests: they work on preprocessed tokens only.
#pragma once

#include <string>

#include "rule/rule.h"

namespace shaderport::rule::testing {

// Renames every identifier `from` to `to`; optionally only in expansions on `only_line`.
class RenameRule : public Rule {
 public:
  RenameRule(std::string id, std::string from, std::string to, uint32_t only_line = 0)
      : id_(std::move(id)), from_(std::move(from)), to_(std::move(to)), only_line_(only_line) {
    info_ = {id_, "renames an identifier", from_, to_, RuleScope::kAlways};
  }
  const RuleInfo& Info() const override { return info_; }
  void Run(RuleContext& context) const override {
    for (const glsl::PpToken& token : context.Preprocessed().tokens) {
      if (token.kind != glsl::TokenKind::kIdentifier || token.text != from_) continue;
      if (token.spelling.file != context.File().Id()) continue;
      if (only_line_ != 0 && context.File().LocationOf(token.expansion.begin).line != only_line_) {
        continue;
      }
      Diagnostic d;
      d.severity = Severity::kWarning;
      d.rule_id = id_;
      d.range = token.expansion;
      d.message = "'" + from_ + "' is renamed";
      d.fixes.push_back({token.spelling, to_, FixSafety::kSafe});
      context.Report(std::move(d));
    }
  }

 private:
  std::string id_, from_, to_;
  uint32_t only_line_;
  RuleInfo info_;
};

// Reports every identifier `name` without a fix.
class FlagRule : public Rule {
 public:
  explicit FlagRule(std::string name) : name_(std::move(name)) {
    info_ = {"test/flag", "flags a name", "", "", RuleScope::kPort};
  }
  const RuleInfo& Info() const override { return info_; }
  void Run(RuleContext& context) const override {
    for (const glsl::PpToken& token : context.Preprocessed().tokens) {
      if (token.kind == glsl::TokenKind::kIdentifier && token.text == name_) {
        context.Report({Severity::kWarning, "test/flag", token.expansion, "found", {}, {}});
      }
    }
  }

 private:
  std::string name_;
  RuleInfo info_;
};

}  // namespace shaderport::rule::testing
