#include "driver/webgl_checks.h"

#include <algorithm>
#include <array>
#include <string_view>

#include "rule/rule_context.h"
#include "rules/registry.h"
#include "rules/webgl/glslang_divergence.h"

namespace shaderport::driver {
namespace {

// Front-end findings that are WebGL rules rather than glslang's (glslang has no
// identifier length limit): they count even though glslang also runs.
bool IsWebglFrontEndRule(std::string_view rule_id) {
  static constexpr std::array<std::string_view, 4> kIds = {
      "preprocessor/identifier-too-long", "preprocessor/token-too-long",
      "preprocessor/predefined-macro", "preprocessor/line-too-large"};
  return std::find(kIds.begin(), kIds.end(), rule_id) != kIds.end();
}

int VersionOf(const FrontEndResult& front, const WebglCheckSettings& settings) {
  if (settings.forced_version != 0) return settings.forced_version;
  return settings.shadertoy ? 300 : front.preprocessed.version.number;
}

rules::BrowserContext ToBrowserContext(const FrontEndResult& front,
                                       const WebglCheckSettings& settings) {
  rules::BrowserContext context;
  context.target = settings.target;
  context.extensions = settings.extensions;
  context.version = VersionOf(front, settings);
  context.stage = settings.stage;
  context.file = nullptr;
  context.lexed = &front.lexed;
  context.tree = &front.parsed.tree;
  context.model = front.model ? &*front.model : nullptr;
  context.preprocessed = &front.preprocessed;
  context.front_end_errors = front.HasErrors();
  context.behind_header = settings.behind_header;
  context.first_lines = &front.first_lines;
  return context;
}

}  // namespace

DiagnosticList RunWebglChecks(const SourceFile& file, const FrontEndResult& front,
                              const WebglCheckSettings& settings) {
  DiagnosticList found;
  for (const Diagnostic& diagnostic : front.diagnostics) {
    if (IsWebglFrontEndRule(diagnostic.rule_id)) found.push_back(diagnostic);
  }
  if (!front.model) return found;
  rule::PortSettings port_settings;
  port_settings.mode = rule::PortMode::kFix;
  port_settings.stage = settings.stage;
  port_settings.source_version = VersionOf(front, settings);
  port_settings.written_version =
      front.preprocessed.version.present ? front.preprocessed.version.number : 0;
  port_settings.target = settings.target;
  port_settings.extensions = settings.extensions;
  port_settings.behind_site_header = settings.behind_header;
  for (const rule::Rule* check : rules::CheckRules()) {
    rule::RuleContext context(file, front.lexed, front.preprocessed, front.parsed.tree,
                              *front.model, port_settings);
    check->Run(context);
    for (Diagnostic& diagnostic : context.TakeDiagnostics()) found.push_back(std::move(diagnostic));
  }
  return found;
}

void AlignGlslangWithBrowser(const SourceFile& file, const FrontEndResult& front,
                             const WebglCheckSettings& settings,
                             DiagnosticList& glslang_diagnostics) {
  rules::BrowserContext context = ToBrowserContext(front, settings);
  context.file = &file;
  for (Diagnostic& diagnostic : glslang_diagnostics) {
    rules::AlignWithBrowser(context, diagnostic);
  }
}

rules::GlslangText TextForGlslang(const SourceFile& file, const SourceFile* common,
                                  const SourceFile& part, const FrontEndResult& front,
                                  const WebglCheckSettings& settings) {
  rules::BrowserContext context = ToBrowserContext(front, settings);
  context.file = &file;
  if (common != nullptr) context.parts.push_back(common);
  context.parts.push_back(&file);
  return rules::TextForGlslang(context, part);
}

std::string ExpandedTextForGlslang(const SourceFile& file, const SourceFile& part,
                                   const FrontEndResult& front,
                                   const WebglCheckSettings& settings) {
  rules::BrowserContext context = ToBrowserContext(front, settings);
  context.file = &file;
  return rules::ExpandedTextForGlslang(context, part);
}

}  // namespace shaderport::driver
