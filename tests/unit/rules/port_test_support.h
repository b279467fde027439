// Helpers for the webgl2/* rule tests: run one rule on a text and apply its safe
// fixes, port with every webgl2/* rule through the fix engine, compile with glslang.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.h"
#include "finding_format.h"
#include "rule/fix_engine.h"
#include "rule/rule.h"
#include "rule/rule_context.h"
#include "rules/registry.h"
#include "source/edit.h"
#include "source/source_file.h"
#include "validate/glslang_validator.h"

namespace shaderport::port_test {

struct RuleRun {
  DiagnosticList diagnostics;
  std::string fixed;  // the text with the rule's non-overlapping safe fixes applied
};

inline rule::PortSettings Settings(model::Stage stage, rule::PortMode mode, int version) {
  rule::PortSettings settings;
  settings.stage = stage;
  settings.mode = mode;
  settings.source_version = version;
  return settings;
}

inline RuleRun RunOneRule(const rule::Rule& r, const std::string& text, model::Stage stage,
                          rule::PortMode mode = rule::PortMode::kPort, int version = 100) {
  const SourceFile file(0, "input", text);
  const rule::AnalyzedShader analyzed = rule::AnalyzePlain(file, 0, stage);
  const rule::PortSettings settings = Settings(stage, mode, version);
  rule::RuleContext context(file, *analyzed.lexed, *analyzed.preprocessed, *analyzed.tree,
                            *analyzed.model, settings);
  r.Run(context);
  RuleRun run;
  run.diagnostics = context.TakeDiagnostics();
  std::vector<Edit> edits;
  for (const Diagnostic& d : run.diagnostics) {
    std::vector<Edit> mine;
    for (const FixIt& fix : d.fixes) {
      if (fix.safety == FixSafety::kSafe)
        mine.push_back({fix.range.begin, fix.range.end, fix.replacement});
    }
    bool clash = false;
    for (const Edit& a : mine) {
      for (const Edit& b : edits) clash = clash || EditsOverlap(a, b);
    }
    if (!clash) edits.insert(edits.end(), mine.begin(), mine.end());
  }
  auto applied = ApplyEdits(text, edits);
  run.fixed = applied ? applied->text : text;
  return run;
}

inline std::vector<const rule::Rule*> PortRules() {
  std::vector<const rule::Rule*> selected;
  for (const rule::Rule* r : rules::AllRules()) {
    if (r->Info().id.starts_with("port/")) selected.push_back(r);
  }
  return selected;
}

inline rule::FixEngineResult PortWithPortRules(const std::string& text, model::Stage stage,
                                               int version = 100) {
  const SourceFile file(0, "input", text);
  rule::FixEngineOptions options;
  options.settings = Settings(stage, rule::PortMode::kPort, version);
  options.rules = PortRules();
  options.analyze = [stage](const SourceFile& f) { return rule::AnalyzePlain(f, 0, stage); };
  return rule::RunFixEngine(file, options);
}

inline validate::ValidationResult Compile(const std::string& text, model::Stage stage) {
  validate::ValidationRequest request;
  request.parts.push_back({"input", text, 0, validate::PartKind::kUser});
  request.stage = stage;
  request.default_version = 100;
  return validate::ValidateWithGlslang(request);
}

inline std::string Messages(const validate::ValidationResult& result) {
  std::string out;
  for (const Diagnostic& d : result.diagnostics) out += d.message + "\n";
  return out;
}

}  // namespace shaderport::port_test
