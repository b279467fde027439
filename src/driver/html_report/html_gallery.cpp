#include "driver/html_report/html_gallery.h"

#include <utility>

#include "driver/html_report/png_base64.h"

namespace shaderport::driver {
namespace {

bool AnyStep(const ReportEntry& entry, StepStatus status) {
  return entry.check.status == status || entry.port.status == status ||
         entry.render.status == status;
}

// The step badge colours (html_report.cpp's style) for each tile status.
const char* BadgeColour(EntryStatus status) {
  switch (status) {
    case EntryStatus::kFail:
      return "fail";
    case EntryStatus::kWarn:
      return "warn";
    case EntryStatus::kNotRendered:
      return "skipped";
    case EntryStatus::kPass:
      break;
  }
  return "pass";
}

// "fails: check, port": which steps, since a failing check can sit beside a picture
// (the port fixed it).
std::string BadgeText(const ReportEntry& entry, EntryStatus status) {
  std::string text = EntryStatusLabel(status);
  if (status != EntryStatus::kFail && status != EntryStatus::kWarn) return text;
  const StepStatus worst = status == EntryStatus::kFail ? StepStatus::kFail : StepStatus::kWarn;
  const char* separator = ": ";
  for (const auto& [name, step] : {std::pair{"check", &entry.check}, std::pair{"port", &entry.port},
                                   std::pair{"render", &entry.render}}) {
    if (step->status != worst) continue;
    text += separator;
    text += name;
    separator = ", ";
  }
  return text;
}

void AppendFilterLabel(std::string& out, std::string_view id, std::string_view label,
                       size_t count) {
  out += "<label for=\"filter-" + std::string(id) + "\">" + std::string(label) + " (" +
         std::to_string(count) + ")</label>";
}

void AppendTile(std::string& out, const ReportEntry& entry, size_t index) {
  const EntryStatus status = StatusOfEntry(entry);
  const std::string path = HtmlEscape(entry.path);
  out += "<a class=\"tile " + std::string(EntryStatusClass(status)) + "\" href=\"#" +
         EntryAnchor(index) + "\" title=\"" + path + "\">";
  if (entry.png.empty()) {
    out += "<span class=\"pic\">no picture</span>";
  } else {
    out += "<span class=\"pic\"><img alt=\"render of " + path + "\" src=\"" +
           PngDataUri(entry.png) + "\"></span>";
  }
  out += "<span class=\"badge " + std::string(BadgeColour(status)) + "\">" +
         BadgeText(entry, status) + "</span><span class=\"name\">" + path + "</span></a>\n";
}

}  // namespace

const std::string_view kGalleryStyle =
    R"(input.filter{position:absolute;opacity:0;pointer-events:none}
.filters label{display:inline-block;padding:.15em .8em;margin-right:.4em;border:1px solid #bbb;border-radius:1em;background:#fff;cursor:pointer;font-size:.9em}
#filter-all:checked~#gallery label[for=filter-all],#filter-fail:checked~#gallery label[for=filter-fail],#filter-warn:checked~#gallery label[for=filter-warn]{background:#333;border-color:#333;color:#fff}
#filter-fail:checked~#gallery .tile:not(.is-fail),#filter-fail:checked~#shaders .shader:not(.is-fail),#filter-warn:checked~#gallery .tile:not(.is-warn),#filter-warn:checked~#shaders .shader:not(.is-warn){display:none}
.tiles{display:flex;flex-wrap:wrap;gap:.7em;margin:.8em 0 2em}
.tile{display:flex;flex-direction:column;gap:4px;width:128px;padding:6px;background:#fff;border:1px solid #ddd;border-radius:6px;color:#222;text-decoration:none}
.tile:hover{border-color:#666}.tile.is-fail{border-color:#e5a0a0}
.pic{width:128px;height:128px;background:#eee;display:flex;align-items:center;justify-content:center;color:#888;font-size:.8em}
.pic img{width:128px;height:128px;image-rendering:pixelated}
.tile .badge{align-self:flex-start}.name{font-family:monospace;font-size:.75em;overflow-wrap:anywhere}
)";

EntryStatus StatusOfEntry(const ReportEntry& entry) {
  if (AnyStep(entry, StepStatus::kFail)) return EntryStatus::kFail;
  if (AnyStep(entry, StepStatus::kWarn)) return EntryStatus::kWarn;
  if (entry.png.empty()) return EntryStatus::kNotRendered;
  return EntryStatus::kPass;
}

const char* EntryStatusClass(EntryStatus status) {
  switch (status) {
    case EntryStatus::kFail:
      return "is-fail";
    case EntryStatus::kWarn:
      return "is-warn";
    case EntryStatus::kNotRendered:
      return "is-not-rendered";
    case EntryStatus::kPass:
      break;
  }
  return "is-pass";
}

const char* EntryStatusLabel(EntryStatus status) {
  switch (status) {
    case EntryStatus::kFail:
      return "fails";
    case EntryStatus::kWarn:
      return "warnings";
    case EntryStatus::kNotRendered:
      return "not rendered";
    case EntryStatus::kPass:
      break;
  }
  return "passes";
}

std::string EntryAnchor(size_t index) { return "shader-" + std::to_string(index + 1); }

void AppendFilterInputs(std::string& out) {
  out +=
      "<input type=\"radio\" class=\"filter\" name=\"filter\" id=\"filter-all\" checked>"
      "<input type=\"radio\" class=\"filter\" name=\"filter\" id=\"filter-fail\">"
      "<input type=\"radio\" class=\"filter\" name=\"filter\" id=\"filter-warn\">\n";
}

void AppendGallery(std::string& out, const HtmlReport& report) {
  size_t failing = 0;
  size_t warning = 0;
  for (const ReportEntry& entry : report.entries) {
    const EntryStatus status = StatusOfEntry(entry);
    failing += status == EntryStatus::kFail ? 1 : 0;
    warning += status == EntryStatus::kWarn ? 1 : 0;
  }
  out += "<section id=\"gallery\">\n<div class=\"filters\">show: ";
  AppendFilterLabel(out, "all", "all", report.entries.size());
  AppendFilterLabel(out, "fail", "failing", failing);
  AppendFilterLabel(out, "warn", "warnings", warning);
  out += "</div>\n<div class=\"tiles\">\n";
  for (size_t i = 0; i < report.entries.size(); ++i) AppendTile(out, report.entries[i], i);
  out += "</div>\n</section>\n";
}

}  // namespace shaderport::driver
