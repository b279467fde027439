#include "report/output_format.h"

#include "report/github_format.h"
#include "report/json_format.h"
#include "report/sarif_format.h"
#include "report/text_format.h"

namespace shaderport {

std::optional<OutputFormat> ParseOutputFormat(std::string_view name) {
  if (name == "text") return OutputFormat::kText;
  if (name == "json") return OutputFormat::kJson;
  if (name == "sarif") return OutputFormat::kSarif;
  if (name == "github") return OutputFormat::kGithub;
  return std::nullopt;
}

std::string_view OutputFormatName(OutputFormat format) {
  switch (format) {
    case OutputFormat::kText:
      return "text";
    case OutputFormat::kJson:
      return "json";
    case OutputFormat::kSarif:
      return "sarif";
    case OutputFormat::kGithub:
      return "github";
  }
  return "text";
}

std::string FormatReport(const CheckReport& report, OutputFormat format,
                         const ReportOptions& options) {
  switch (format) {
    case OutputFormat::kText:
      return FormatText(report, options);
    case OutputFormat::kJson:
      return FormatJson(report, options);
    case OutputFormat::kSarif:
      return FormatSarif(report, options);
    case OutputFormat::kGithub:
      return FormatGithub(report, options);
  }
  return FormatText(report, options);
}

}  // namespace shaderport
