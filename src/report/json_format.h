// The machine format, version 1: one JSON document, specified by
// docs/shaderport-diagnostics.schema.json and described in docs/output-formats.md.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "report/check_report.h"

namespace shaderport {

inline constexpr int kJsonFormatVersion = 1;

nlohmann::ordered_json ReportToJson(const CheckReport& report, const ReportOptions& options);

// Pretty-printed with two-space indents and a final newline.
std::string FormatJson(const CheckReport& report, const ReportOptions& options);

}  // namespace shaderport
