// libFuzzer target for the output formats (src/report): a report of fuzzer-chosen
// files (names, text), rule ids, messages, notes, fix-its and ranges is printed in
// every format. JSON and SARIF output always parse as JSON; GitHub output is one
// workflow command a line (no raw newline or carriage return inside a command).
#include <fuzzer/FuzzedDataProvider.h>

#include <cstdint>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "fuzz_check.h"
#include "report/check_report.h"
#include "report/output_format.h"

namespace {

void Require(bool ok, const char* what) { shaderport::fuzz::Check(ok, "fuzz_formatters", what); }

// A range in one of the files (or none), begin <= end, inside that file.
shaderport::SourceRange PickRange(FuzzedDataProvider& in,
                                  const shaderport::SourceManager& sources) {
  const auto file = in.ConsumeIntegralInRange<uint32_t>(0, static_cast<uint32_t>(sources.Size()));
  if (file == sources.Size()) return {};
  const auto size = static_cast<uint32_t>(sources.Get(file).Text().size());
  uint32_t begin = in.ConsumeIntegralInRange<uint32_t>(0, size);
  uint32_t end = in.ConsumeIntegralInRange<uint32_t>(0, size);
  if (begin > end) std::swap(begin, end);
  return {file, begin, end};
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace shaderport;
  FuzzedDataProvider in(data, size);
  SourceManager sources;
  const int file_count = in.ConsumeIntegralInRange(1, 3);
  for (int i = 0; i < file_count; ++i) {
    std::string name = in.ConsumeRandomLengthString(64);
    std::string text = in.ConsumeRandomLengthString(512);
    sources.Add(std::move(name), std::move(text), in.ConsumeBool());
  }
  CheckReport report;
  report.sources = &sources;
  for (int i = 0; i < file_count; ++i) {
    FileReport file;
    file.file = &sources.Get(static_cast<FileId>(i));
    file.dialect = in.ConsumeBool() ? "shadertoy" : in.ConsumeRandomLengthString(12);
    file.stage = in.ConsumeBool() ? "fragment" : "vertex";
    const int count = in.ConsumeIntegralInRange(0, 6);
    for (int d = 0; d < count; ++d) {
      Diagnostic diagnostic;
      diagnostic.severity = static_cast<Severity>(in.ConsumeIntegralInRange(0, 2));
      diagnostic.rule_id = in.ConsumeRandomLengthString(40);
      diagnostic.range = PickRange(in, sources);
      diagnostic.message = in.ConsumeRandomLengthString(160);
      for (int n = in.ConsumeIntegralInRange(0, 2); n > 0; --n) {
        const SourceRange range = PickRange(in, sources);
        diagnostic.notes.push_back({range, in.ConsumeRandomLengthString(80)});
      }
      for (int f = in.ConsumeIntegralInRange(0, 2); f > 0; --f) {
        FixIt fix;
        fix.range = PickRange(in, sources);
        fix.replacement = in.ConsumeRandomLengthString(40);
        fix.safety = in.ConsumeBool() ? FixSafety::kSafe : FixSafety::kSuggestion;
        diagnostic.fixes.push_back(std::move(fix));
      }
      file.diagnostics.push_back(std::move(diagnostic));
    }
    report.files.push_back(std::move(file));
  }
  ReportOptions options;
  options.tool_version = "0.1.0";
  if (in.ConsumeBool()) options.base_directory = "/" + in.ConsumeRandomLengthString(32);
  options.rules_with_sections = {"glslang/syntax", "webgl/no-precision"};
  SortReport(report);

  (void)FormatReport(report, OutputFormat::kText, options);
  for (OutputFormat format : {OutputFormat::kJson, OutputFormat::kSarif}) {
    const std::string out = FormatReport(report, format, options);
    Require(!nlohmann::json::parse(out, nullptr, false).is_discarded(),
            format == OutputFormat::kJson ? "JSON output does not parse"
                                          : "SARIF output does not parse");
  }
  const std::string github = FormatReport(report, OutputFormat::kGithub, options);
  Require(github.find('\r') == std::string::npos, "raw carriage return in GitHub output");
  std::istringstream lines(github);
  for (std::string line; std::getline(lines, line);) {
    Require(line.starts_with("::error") || line.starts_with("::warning") ||
                line.starts_with("::notice"),
            "a GitHub output line is not a workflow command");
  }
  return 0;
}
