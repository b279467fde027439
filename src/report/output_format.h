// The `--format` choices of `shaderport check` and one entry point for all of them.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "report/check_report.h"

namespace shaderport {

enum class OutputFormat { kText, kJson, kSarif, kGithub };

// "text", "json", "sarif", "github"; nullopt for anything else.
std::optional<OutputFormat> ParseOutputFormat(std::string_view name);
std::string_view OutputFormatName(OutputFormat format);

std::string FormatReport(const CheckReport& report, OutputFormat format,
                         const ReportOptions& options);

}  // namespace shaderport
