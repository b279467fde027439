// A ShaderToy project (JSON document or project folder) in the HTML report: one
// entry for all its passes, ported as a project and drawn with every pass.
#pragma once

#include <filesystem>
#include <vector>

#include "driver/html_report/build_report.h"
#include "report/check_report.h"

namespace shaderport::driver {

// `project` is the .json/.jsonl file or the folder; `checked` its passes' reports.
void FillProjectEntry(const std::filesystem::path& project,
                      const std::vector<const FileReport*>& checked,
                      const HtmlReportOptions& options, SourceManager& sources, ReportEntry& entry);

// The project a checked file belongs to ("" when none): the JSON document a pass
// is embedded in, or the project folder of a tab file.
std::filesystem::path ProjectOfReport(const FileReport& report);

}  // namespace shaderport::driver
