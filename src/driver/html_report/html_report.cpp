#include "driver/html_report/html_report.h"

#include "driver/html_report/html_findings.h"
#include "driver/html_report/html_gallery.h"

namespace shaderport::driver {
namespace {

constexpr std::string_view kStyle =
    R"(body{font-family:system-ui,sans-serif;margin:2em;color:#222;background:#fafafa}
h1{font-size:1.4em}h2{font-size:1.05em;margin:0 0 .3em;font-family:monospace}
table.summary{border-collapse:collapse;margin-bottom:2em}
table.summary td,table.summary th{border:1px solid #ccc;padding:.25em .7em;text-align:right}
table.summary th:first-child{text-align:left}
.shader{background:#fff;border:1px solid #ddd;border-radius:6px;padding:.8em;margin-bottom:1em}
.meta{color:#666;font-size:.9em;margin-bottom:.4em}.top{float:right;font-size:.8em}
.badge{display:inline-block;padding:.1em .5em;border-radius:3px;font-size:.8em;color:#fff;margin-right:.4em}
.pass{background:#2e7d32}.warn{background:#ef8f00}.fail{background:#c62828}.skipped{background:#888}
.step{margin:.2em 0}.detail{color:#555;font-size:.9em}
pre{background:#f4f4f4;padding:.5em;overflow-x:auto;font-size:.8em;margin:.2em 0 .5em}
details.cascade{margin:-.4em 0 .5em 1em;font-size:.85em}details.cascade summary{cursor:pointer;color:#555}
)";

void Count(StepStatus status, StepCounts& counts) {
  switch (status) {
    case StepStatus::kPass:
      ++counts.pass;
      break;
    case StepStatus::kWarn:
      ++counts.warn;
      break;
    case StepStatus::kFail:
      ++counts.fail;
      break;
    case StepStatus::kSkipped:
      ++counts.skipped;
      break;
  }
}

std::string Badge(std::string_view label, StepStatus status) {
  const std::string name = StepStatusName(status);
  return "<span class=\"badge " + name + "\">" + std::string(label) + ": " + name + "</span>";
}

void AppendCountRow(std::string& out, std::string_view label, const StepCounts& counts) {
  out += "<tr><th>" + std::string(label) + "</th><td>" + std::to_string(counts.pass) + "</td><td>" +
         std::to_string(counts.warn) + "</td><td>" + std::to_string(counts.fail) + "</td><td>" +
         std::to_string(counts.skipped) + "</td></tr>\n";
}

void AppendStep(std::string& out, std::string_view label, const ReportStep& step) {
  out += "<div class=\"step\">" + Badge(label, step.status);
  if (!step.detail.empty()) out += "<span class=\"detail\">" + HtmlEscape(step.detail) + "</span>";
  out += "</div>\n";
  AppendFindings(out, step.findings);
}

}  // namespace

const char* StepStatusName(StepStatus status) {
  switch (status) {
    case StepStatus::kPass:
      return "pass";
    case StepStatus::kWarn:
      return "warn";
    case StepStatus::kFail:
      return "fail";
    case StepStatus::kSkipped:
      break;
  }
  return "skipped";
}

ReportCounts CountReport(const HtmlReport& report) {
  ReportCounts counts;
  for (const ReportEntry& entry : report.entries) {
    if (!entry.shader) continue;
    ++counts.shaders;
    Count(entry.check.status, counts.check);
    Count(entry.port.status, counts.port);
    Count(entry.render.status, counts.render);
    if (!entry.png.empty()) ++counts.thumbnails;
  }
  return counts;
}

std::string HtmlEscape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string FormatHtmlReport(const HtmlReport& report) {
  const ReportCounts counts = CountReport(report);
  std::string out;
  // The page needs no script and loads nothing: a policy that forbids both is a
  // second wall behind the escaping, should a payload in shader text get through.
  out +=
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; "
      "img-src data:; style-src 'unsafe-inline'\">\n<title>" +
      HtmlEscape(report.title) + "</title>\n<style>\n";
  out += kStyle;
  out += kGalleryStyle;
  out += "</style>\n</head>\n<body>\n<h1>" + HtmlEscape(report.title) + "</h1>\n";
  out += "<p class=\"meta\">shaderport " + HtmlEscape(report.tool_version) + " &middot; " +
         std::to_string(counts.shaders) + " shaders &middot; renders " +
         std::to_string(report.render_size) + "&times;" + std::to_string(report.render_size) +
         " (ported shader, or the site composition when the port fails)</p>\n";

  // The pictures are why the page is opened: they come first, findings one click away.
  AppendFilterInputs(out);
  AppendGallery(out, report);

  out += "<section id=\"summary\">\n<h2>Summary</h2>\n<table class=\"summary\">\n";
  out += "<tr><th>step</th><th>pass</th><th>warn</th><th>fail</th><th>skipped</th></tr>\n";
  AppendCountRow(out, "check", counts.check);
  AppendCountRow(out, "port", counts.port);
  AppendCountRow(out, "render", counts.render);
  out += "</table>\n<p>" + std::to_string(counts.thumbnails) + " of " +
         std::to_string(counts.shaders) + " shaders rendered a picture.</p>\n";
  if (!report.errors.empty()) {
    out += "<h2>Input errors</h2>\n<pre>";
    for (const std::string& error : report.errors) out += HtmlEscape(error) + "\n";
    out += "</pre>\n";
  }
  out += "</section>\n";

  out += "<section id=\"shaders\">\n";
  for (size_t i = 0; i < report.entries.size(); ++i) {
    const ReportEntry& entry = report.entries[i];
    // The status class lets the gallery's filters hide details too.
    out += "<div class=\"shader " + std::string(EntryStatusClass(StatusOfEntry(entry))) +
           "\" id=\"" + EntryAnchor(i) + "\">\n<a class=\"top\" href=\"#gallery\">gallery</a>\n";
    out += "<h2>" + HtmlEscape(entry.path) + "</h2>\n";
    out += "<div class=\"meta\">" +
           HtmlEscape(entry.dialect.empty() ? "unknown dialect" : entry.dialect) + " &middot; " +
           HtmlEscape(entry.stage.empty() ? "unknown stage" : entry.stage) + "</div>\n";
    AppendStep(out, "check", entry.check);
    AppendStep(out, "port", entry.port);
    AppendStep(out, "render", entry.render);
    out += "</div>\n";
  }
  out += "</section>\n</body>\n</html>\n";
  return out;
}

}  // namespace shaderport::driver
