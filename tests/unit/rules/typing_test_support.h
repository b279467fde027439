// Helpers for the typing/* rule tests: analyse plain or ShaderToy code, run one
// rule, fix with every typing/* rule through the fix engine (in the file's own
// dialect, as `shaderport fix` does), and compile the result with glslang.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "diag/diagnostic.h"
#include "glsl/lex/lexer.h"
#include "glsl/syntax/parser.h"
#include "rule/fix_engine.h"
#include "rule/rule.h"
#include "rule/rule_context.h"
#include "rules/registry.h"
#include "sema/sema_test_util.h"
#include "source/source_manager.h"
#include "validate/glslang_validator.h"
#include "validate/shadertoy_contract.h"

namespace shaderport::typing_test {

enum class Kind { kWebGL, kShaderToy };

struct Owned {
  glsl::LexedFile lexed;
  glsl::PreprocessResult preprocessed;
  glsl::ParseResult parsed;
  glsl::SemanticModel model;
};

// ShaderToy code: GLSL ES 3.00 behind the site's uniforms, HW_PERFORMANCE defined.
inline rule::AnalyzedShader AnalyzeShaderToy(const SourceFile& file) {
  auto owned = std::make_shared<Owned>();
  owned->lexed = glsl::Lex(file);
  const std::vector<const SourceFile*> files = {&file};
  glsl::PreprocessOptions pp;
  pp.predefined = {"HW_PERFORMANCE=1"};
  owned->preprocessed = glsl::Preprocess(files, pp);
  glsl::ParseOptions parse;
  parse.version = glsl::kEssl300;
  owned->parsed = glsl::Parse(owned->preprocessed, parse);
  glsl::AnalyzeOptions analyze;
  analyze.version = glsl::kEssl300;
  analyze.predeclared = glsl::testing::ShaderToyUniforms();
  owned->model = glsl::Analyze(owned->parsed.tree, analyze);
  rule::AnalyzedShader shader;
  shader.lexed = &owned->lexed;
  shader.preprocessed = &owned->preprocessed;
  shader.tree = &owned->parsed.tree;
  shader.model = &owned->model;
  shader.diagnostics = owned->parsed.diagnostics;
  shader.owner = owned;
  return shader;
}

inline rule::Analyzer AnalyzerFor(Kind kind, model::Stage stage) {
  if (kind == Kind::kShaderToy) return AnalyzeShaderToy;
  return [stage](const SourceFile& f) { return rule::AnalyzePlain(f, 0, stage); };
}

// A ShaderToy-like harness: entry point mainImage.
inline const model::HarnessDialect* ShaderToyHarness() {
  static const model::HarnessDialect harness = [] {
    model::HarnessDialect h;
    h.name = "shadertoy";
    h.entry_points.push_back({});
    h.entry_points.back().function = "mainImage";
    return h;
  }();
  return &harness;
}

inline rule::PortSettings FixSettings(Kind kind, model::Stage stage) {
  rule::PortSettings settings;
  settings.mode = rule::PortMode::kFix;
  settings.stage = stage;
  settings.source_version = kind == Kind::kShaderToy ? 300 : 100;
  if (kind == Kind::kShaderToy) settings.harness = ShaderToyHarness();
  return settings;
}

inline std::vector<const rule::Rule*> TypingRules() {
  std::vector<const rule::Rule*> selected;
  for (const rule::Rule* r : rules::AllRules()) {
    if (r->Info().id.starts_with("typing/")) selected.push_back(r);
  }
  return selected;
}

// What `rule_id` alone reports on `text`.
inline DiagnosticList RunOneRule(const rule::Rule& r, const std::string& text, Kind kind,
                                 model::Stage stage) {
  const SourceFile file(0, "input", text);
  const rule::AnalyzedShader analyzed = AnalyzerFor(kind, stage)(file);
  const rule::PortSettings settings = FixSettings(kind, stage);
  rule::RuleContext context(file, *analyzed.lexed, *analyzed.preprocessed, *analyzed.tree,
                            *analyzed.model, settings);
  r.Run(context);
  return context.TakeDiagnostics();
}

// `shaderport fix` with the typing rules only.
inline rule::FixEngineResult FixTyping(const std::string& text, Kind kind, model::Stage stage) {
  const SourceFile file(0, "input", text);
  rule::FixEngineOptions options;
  options.settings = FixSettings(kind, stage);
  options.rules = TypingRules();
  options.analyze = AnalyzerFor(kind, stage);
  return rule::RunFixEngine(file, options);
}

// glslang's verdict on the text in its dialect: ShaderToy code under the site's
// contract (Image pass), WebGL code as written (ESSL 1.00 without #version).
inline validate::ValidationResult Compile(const std::string& text, Kind kind, model::Stage stage,
                                          bool* accepted) {
  SourceManager sources;
  const SourceFile& file = sources.Add("input", text);
  validate::ValidationRequest request;
  if (kind == Kind::kShaderToy) {
    request = validate::ComposeShaderToyRequest(sources, model::PassKind::kImage,
                                                model::ChannelKinds{}, nullptr, file);
  } else {
    request.parts.push_back({"input", file.Text(), file.Id(), validate::PartKind::kUser});
    request.stage = stage;
    request.default_version = 100;
  }
  validate::ValidationResult result = validate::ValidateWithGlslang(request);
  *accepted = result.Accepted(request.link);
  return result;
}

inline std::string Messages(const validate::ValidationResult& result) {
  std::string out;
  for (const Diagnostic& d : result.diagnostics) out += d.message + "\n";
  return out;
}

}  // namespace shaderport::typing_test
