#include "report/statistics.h"

#include <algorithm>
#include <map>

#include "diag/rule_catalog.h"

namespace shaderport {

std::vector<RuleCount> CountByRule(const CheckReport& report) {
  std::map<std::string, RuleCount, std::less<>> by_id;
  for (const FileReport& file : report.files) {
    for (const Diagnostic& diagnostic : file.diagnostics) {
      RuleCount& entry = by_id[diagnostic.rule_id];
      if (entry.count == 0) {
        entry.rule_id = diagnostic.rule_id;
        entry.severity = diagnostic.severity;
      }
      ++entry.count;
      entry.severity = std::max(entry.severity, diagnostic.severity);
    }
  }
  std::vector<RuleCount> counts;
  for (auto& [id, entry] : by_id) {
    if (const RuleDescription* description = FindRule(id)) entry.summary = description->summary;
    counts.push_back(std::move(entry));
  }
  std::stable_sort(counts.begin(), counts.end(), [](const RuleCount& a, const RuleCount& b) {
    return a.count > b.count;  // ties keep the map's id order
  });
  return counts;
}

std::string FormatStatistics(const std::vector<RuleCount>& counts) {
  size_t count_width = 0;
  size_t id_width = 0;
  size_t severity_width = 0;
  for (const RuleCount& entry : counts) {
    count_width = std::max(count_width, std::to_string(entry.count).size());
    id_width = std::max(id_width, entry.rule_id.size());
    severity_width =
        std::max(severity_width, std::string_view(SeverityName(entry.severity)).size());
  }
  std::string out;
  for (const RuleCount& entry : counts) {
    const std::string count = std::to_string(entry.count);
    const std::string_view severity = SeverityName(entry.severity);
    out += std::string(count_width - count.size(), ' ') + count + "  ";
    out += entry.rule_id + std::string(id_width - entry.rule_id.size(), ' ') + "  ";
    out += std::string(severity);
    if (!entry.summary.empty()) {
      out += std::string(severity_width - severity.size(), ' ') + "  ";
      out += entry.summary;
    }
    out += '\n';
  }
  return out;
}

}  // namespace shaderport
