#include "driver/html_report/html_findings.h"

#include <map>
#include <string_view>

namespace shaderport::driver {
namespace {

// For each finding, the indices folded under it (empty for most), and which are folded.
struct Folding {
  std::vector<std::vector<size_t>> followers;
  std::vector<bool> folded;
};

Folding FoldCascades(const std::vector<ReportFinding>& findings) {
  Folding folding;
  folding.followers.resize(findings.size());
  folding.folded.resize(findings.size(), false);
  std::map<std::string_view, size_t> heads;  // cascade key -> its first finding
  for (size_t i = 0; i < findings.size(); ++i) {
    const std::string& key = findings[i].cascade;
    if (key.empty()) continue;
    const auto [it, first] = heads.emplace(key, i);
    if (first) continue;
    folding.followers[it->second].push_back(i);
    folding.folded[i] = true;
  }
  return folding;
}

}  // namespace

void AppendFindings(std::string& out, const std::vector<ReportFinding>& findings) {
  const Folding folding = FoldCascades(findings);
  // Shown findings share one <pre> until a fold interrupts it.
  bool open = false;
  for (size_t i = 0; i < findings.size(); ++i) {
    if (folding.folded[i]) continue;
    if (!open) out += "<pre>";
    open = true;
    out += HtmlEscape(findings[i].text);
    const std::vector<size_t>& rest = folding.followers[i];
    if (rest.empty()) continue;
    out += "</pre>\n";
    open = false;
    const std::string count = std::to_string(rest.size());
    out += "<details class=\"cascade\"><summary>+" + count + " more " +
           (rest.size() == 1 ? "error" : "errors") + " from the same compile</summary><pre>";
    for (const size_t j : rest) out += HtmlEscape(findings[j].text);
    out += "</pre></details>\n";
  }
  if (open) out += "</pre>\n";
}

}  // namespace shaderport::driver
