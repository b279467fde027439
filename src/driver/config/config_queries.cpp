#include "driver/config/config.h"
#include "driver/config/glob.h"
#include "driver/config/rule_pattern.h"

namespace shaderport::driver {

std::string_view RuleLevelName(RuleLevel level) {
  switch (level) {
    case RuleLevel::kOff:
      return "off";
    case RuleLevel::kNote:
      return "note";
    case RuleLevel::kWarning:
      return "warning";
    case RuleLevel::kError:
      return "error";
  }
  return "error";
}

std::optional<RuleLevel> ParseRuleLevel(std::string_view name) {
  for (RuleLevel level :
       {RuleLevel::kOff, RuleLevel::kNote, RuleLevel::kWarning, RuleLevel::kError}) {
    if (name == RuleLevelName(level)) return level;
  }
  return std::nullopt;
}

std::optional<RuleLevel> RuleLevelFor(const Config& config, std::string_view rule_id) {
  std::optional<RuleLevel> level;
  int best = -1;
  for (const RuleSetting& setting : config.rules) {
    if (!RulePatternMatches(setting.pattern, rule_id)) continue;
    const int specificity = RulePatternSpecificity(setting.pattern);
    if (specificity >= best) {
      best = specificity;
      level = setting.level;
    }
  }
  return level;
}

void ApplyRuleConfig(const Config& config, DiagnosticList& diagnostics) {
  if (config.rules.empty()) return;
  std::erase_if(diagnostics, [&](Diagnostic& d) {
    const std::optional<RuleLevel> level = RuleLevelFor(config, d.rule_id);
    if (!level) return false;
    switch (*level) {
      case RuleLevel::kOff:
        return true;
      case RuleLevel::kNote:
        d.severity = Severity::kNote;
        break;
      case RuleLevel::kWarning:
        d.severity = Severity::kWarning;
        break;
      case RuleLevel::kError:
        d.severity = Severity::kError;
        break;
    }
    return false;
  });
}

bool FailsCheck(const Config& config, const DiagnosticList& diagnostics) {
  for (const Diagnostic& d : diagnostics) {
    if (d.severity >= config.fail_on) return true;
  }
  return false;
}

std::optional<std::string> PathInConfig(const Config& config, const std::filesystem::path& file) {
  const std::filesystem::path relative =
      file.lexically_normal().lexically_relative(config.directory.lexically_normal());
  if (relative.empty()) return std::nullopt;
  const std::string text = relative.generic_string();
  if (text == ".." || text.starts_with("../")) return std::nullopt;
  return text;
}

bool IsIncluded(const Config& config, const std::filesystem::path& file) {
  const std::optional<std::string> path = PathInConfig(config, file);
  if (!path) return config.include.empty();  // outside the project: only excluded by includes
  bool included = config.include.empty();
  for (const std::string& glob : config.include) included = included || GlobMatches(glob, *path);
  if (!included) return false;
  for (const std::string& glob : config.exclude) {
    if (GlobMatches(glob, *path)) return false;
  }
  return true;
}

FileSettings SettingsFor(const Config& config, const std::filesystem::path& file) {
  FileSettings settings;
  const std::optional<std::string> path = PathInConfig(config, file);
  if (!path) return settings;
  for (const FileOverride& entry : config.files) {
    if (!GlobMatches(entry.glob, *path)) continue;
    if (entry.dialect) settings.dialect = entry.dialect;
    if (entry.stage) settings.stage = entry.stage;
    if (entry.target) settings.target = entry.target;
  }
  return settings;
}

}  // namespace shaderport::driver
