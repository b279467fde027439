// Helpers for the harness (shadertoy/*, dialect) tests: run one rule with a
// dialect, port through the fix engine with every rule, compile with glslang.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.h"
#include "finding_format.h"
#include "golden.h"
#include "model/shipped_dialects.h"
#include "rule/fix_engine.h"
#include "rule/rule.h"
#include "rule/rule_context.h"
#include "rules/registry.h"
#include "source/source_file.h"
#include "validate/glslang_validator.h"

namespace shaderport::shadertoy_test {

// ShaderToy code is GLSL ES 3.00 behind the site's header, whose HW_PERFORMANCE
// the analysis must see until the port defines it itself.
// Hosts whose users write main() (glslsandbox...) take WebGL1 code: its own #version.
inline rule::AnalyzedShader AnalyzeHarnessCode(const SourceFile& file, bool shadertoy = true) {
  if (!shadertoy) return rule::AnalyzePlain(file, 0, model::Stage::kFragment);
  std::vector<std::string> predefined;
  if (file.Text().find("#define HW_PERFORMANCE") == std::string_view::npos) {
    predefined.push_back("HW_PERFORMANCE=1");
  }
  return rule::AnalyzePlain(file, 300, model::Stage::kFragment, predefined);
}

inline rule::PortSettings HarnessSettings(const model::HarnessDialect* dialect) {
  rule::PortSettings settings;
  settings.mode = rule::PortMode::kPort;
  settings.stage = model::Stage::kFragment;
  settings.harness = dialect;
  settings.source_version = 300;
  return settings;
}

inline DiagnosticList RunRule(const rule::Rule& r, const std::string& text,
                              const rule::PortSettings& settings) {
  const SourceFile file(0, "input", text);
  const rule::AnalyzedShader analyzed =
      AnalyzeHarnessCode(file, settings.harness && !settings.harness->entry_points.empty());
  rule::RuleContext context(file, *analyzed.lexed, *analyzed.preprocessed, *analyzed.tree,
                            *analyzed.model, settings);
  r.Run(context);
  return context.TakeDiagnostics();
}

// Every registered rule, through the engine, as `shaderport port` would.
inline rule::FixEngineResult Port(const std::string& text, const rule::PortSettings& settings) {
  const SourceFile file(0, "input", text);
  rule::FixEngineOptions options;
  options.settings = settings;
  for (const rule::Rule* r : rules::AllRules()) options.rules.push_back(r);
  const bool shadertoy = settings.harness && !settings.harness->entry_points.empty();
  options.analyze = [shadertoy](const SourceFile& f) { return AnalyzeHarnessCode(f, shadertoy); };
  return rule::RunFixEngine(file, options);
}

inline validate::ValidationResult CompileEssl300(const std::string& text) {
  validate::ValidationRequest request;
  request.parts.push_back({"output", text, 0, validate::PartKind::kUser});
  request.stage = model::Stage::kFragment;
  request.default_version = 300;
  request.link = true;
  return validate::ValidateWithGlslang(request);
}

inline std::string Messages(const validate::ValidationResult& result) {
  std::string out;
  for (const Diagnostic& d : result.diagnostics) out += d.message + "\n";
  return out;
}

}  // namespace shaderport::shadertoy_test
