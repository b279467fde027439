// `shaderport report --html`: every shader file under the given paths through
// check (glslang's verdict), port (WebGL2) and a smoke render, collected into an
// HtmlReport (html_report.h). The CLI writes the page; this does no file output.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "driver/html_report/html_report.h"
#include "render/render_request.h"

namespace shaderport::driver {

struct HtmlReportOptions {
  std::vector<std::filesystem::path> paths;
  unsigned jobs = 0;             // 0: every core
  uint32_t size = 128;           // render width and height
  render::RenderOptions render;  // backend, timeout, Mesa cache
  std::string tool_version;
};

struct HtmlReportRun {
  HtmlReport report;
  std::vector<std::string> usage_errors;  // paths that do not exist (also in report.errors)
  bool found_nothing = false;             // the paths held no shader file (CheckRun's)
};

// Deterministic: the result depends only on the files and the options, never on
// `jobs` or timing.
HtmlReportRun BuildHtmlReport(const HtmlReportOptions& options);

}  // namespace shaderport::driver
