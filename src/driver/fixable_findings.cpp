#include "driver/fixable_findings.h"

#include <algorithm>
#include <vector>

#include "rule/rule_context.h"
#include "rules/registry.h"
#include "validate/shadertoy_contract.h"

namespace shaderport::driver {
namespace {

uint32_t LineOf(const SourceManager& sources, const SourceRange& range) {
  return sources.Get(range.file).LocationOf(range.begin).line;
}

bool Overlaps(const SourceRange& a, const SourceRange& b) {
  if (a.file != b.file) return false;
  // An empty range (an insertion point, a caret) overlaps what it touches.
  return a.begin <= b.end && b.begin <= a.end;
}

// Still reported after the fix: same rule on the same line.
bool Remains(const Diagnostic& finding, const PortResult& fixed, const SourceManager& sources) {
  const uint32_t line = LineOf(sources, finding.range);
  return std::any_of(fixed.diagnostics.begin(), fixed.diagnostics.end(), [&](const Diagnostic& d) {
    return d.rule_id == finding.rule_id && d.range.file == finding.range.file &&
           LineOf(sources, d.range) == line;
  });
}

}  // namespace

PortOptions FixOptionsFor(const FileDecision& decision) {
  PortOptions options;
  options.mode = rule::PortMode::kFix;
  options.dialect = decision.kind.dialect;
  options.stage = decision.kind.stage;
  if (decision.IsShaderToy()) options.pass = decision.kind.pass;
  if (!decision.IsShaderToy()) options.harness = decision.harness;
  for (size_t i = 0; i < decision.channels.size(); ++i) options.channels[i] = decision.channels[i];
  return options;
}

bool FixOffersAnEdit(const SourceFile& file, const FrontEndResult& front,
                     const FileDecision& decision) {
  if (!front.model) return false;
  const PortOptions options = FixOptionsFor(decision);
  rule::PortSettings settings;
  settings.mode = rule::PortMode::kFix;
  settings.stage = decision.kind.stage;
  settings.harness = decision.harness;
  settings.source_version = decision.kind.dialect == Dialect::kWebGL1 ? 100 : 300;
  settings.buffer_pass = decision.kind.pass == model::PassKind::kBuffer;
  for (size_t i = 0; i < 4; ++i) settings.channels[i] = options.channels[i];
  for (const rule::Rule* r : rules::RulesForMode(rule::PortMode::kFix)) {
    rule::RuleContext context(file, front.lexed, front.preprocessed, front.parsed.tree,
                              *front.model, settings);
    r->Run(context);
    for (const Diagnostic& finding : context.TakeDiagnostics()) {
      if (IsFixable(finding)) return true;
    }
  }
  return false;
}

bool AnyFindingWithoutFix(const DiagnosticList& findings) {
  return std::any_of(findings.begin(), findings.end(), [](const Diagnostic& finding) {
    return !IsFixable(finding) && finding.range.file != kNoFile;
  });
}

void AttachRepairs(const PortResult& fixed, const SourceManager& sources,
                   DiagnosticList& findings) {
  if (!fixed.HasOutput() || fixed.fixed.empty() || fixed.file == nullptr) return;
  std::vector<const Diagnostic*> repairs;
  for (const Diagnostic& repair : fixed.fixed) {
    if (IsFixable(repair) && repair.range.file != kNoFile) repairs.push_back(&repair);
  }
  // First the repairs on the finding itself, then those on its line: glslang often
  // points at the operator next to the literal a rule rewrites.
  for (const bool same_line_only : {false, true}) {
    for (Diagnostic& finding : findings) {
      if (IsFixable(finding) || finding.range.file == kNoFile) continue;
      if (Remains(finding, fixed, sources)) continue;
      const uint32_t line = LineOf(sources, finding.range);
      for (const Diagnostic*& repair : repairs) {
        if (repair == nullptr) continue;
        const bool matches = same_line_only ? repair->range.file == finding.range.file &&
                                                  LineOf(sources, repair->range) == line
                                            : Overlaps(repair->range, finding.range);
        if (!matches) continue;
        for (const FixIt& fix : repair->fixes) {
          if (fix.safety == FixSafety::kSafe) finding.fixes.push_back(fix);
        }
        finding.notes.push_back({repair->range, "'shaderport fix' repairs this (" +
                                                    repair->rule_id + "): " + repair->message});
        repair = nullptr;
        break;
      }
    }
  }
}

}  // namespace shaderport::driver
