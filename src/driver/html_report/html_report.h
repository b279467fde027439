// The data of `shaderport report --html` and the page made from it: one
// self-contained HTML file (inline CSS, thumbnails as data: URIs, no scripts), so
// that a person can open the corpus's state in a browser. The page opens on a
// gallery of thumbnails (html_gallery.h); details follow, with compiler cascades
// folded (html_findings.h). Pure formatting: no I/O.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace shaderport::driver {

// The outcome of one step for one shader, shown as a badge.
enum class StepStatus { kPass, kWarn, kFail, kSkipped };
const char* StepStatusName(StepStatus status);  // "pass", "warn", "fail", "skipped"

// One finding of a step: its clang-style text (escaped by the formatter).
struct ReportFinding {
  std::string text;
  // A compiler error's cascade, "" for a finding that stands alone (shaderport's own
  // rules, warnings, notes). Errors with one key came from one compiler run over one
  // file ("glslang 3", "mesa 3"): the page shows the first and folds the rest.
  std::string cascade;
};

struct ReportStep {
  StepStatus status = StepStatus::kSkipped;
  std::string detail;                   // one line beside the badge ("validated", "not rendered")
  std::vector<ReportFinding> findings;  // in position order, none when clean
};

struct ReportEntry {
  std::string path;     // as the user named it
  std::string dialect;  // "shadertoy", "webgl1", "webgl2", "" when unknown
  std::string stage;    // "vertex", "fragment", ""
  ReportStep check;     // glslang verdict and diagnostics
  ReportStep port;      // WebGL2 port
  ReportStep render;    // smoke render of the port (or the site composition)
  std::string png;      // PNG bytes of the thumbnail; empty: none
  bool shader = true;   // false for a .shaderport.toml's findings: shown, not counted
};

struct HtmlReport {
  std::string title = "shaderport report";
  std::string tool_version;
  unsigned render_size = 128;
  std::vector<ReportEntry> entries;  // in path order
  std::vector<std::string> errors;   // inputs that could not be walked
};

struct StepCounts {
  size_t pass = 0;
  size_t warn = 0;
  size_t fail = 0;
  size_t skipped = 0;
};
struct ReportCounts {
  size_t shaders = 0;
  StepCounts check;
  StepCounts port;
  StepCounts render;
  size_t thumbnails = 0;
};
ReportCounts CountReport(const HtmlReport& report);

// `&`, `<`, `>`, `"` and `'` as entities.
std::string HtmlEscape(std::string_view text);

// The whole page. Deterministic: equal reports give equal bytes.
std::string FormatHtmlReport(const HtmlReport& report);

}  // namespace shaderport::driver
