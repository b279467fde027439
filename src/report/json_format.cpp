#include "report/json_format.h"

#include "report/source_position.h"

namespace shaderport {
namespace {

using Json = nlohmann::ordered_json;

Json Position(const LineColumn& at, uint32_t offset) {
  return Json{{"line", at.line}, {"column", at.column}, {"offset", offset}};
}

// {"path", "range": {"start", "end"}} or null when the range points nowhere.
Json Location(const CheckReport& report, const ReportOptions& options, const SourceRange& range) {
  const auto where = Resolve(report.sources, range);
  if (!where) return nullptr;
  return Json{{"path", DisplayPath(where->file->Name(), options.base_directory)},
              {"range",
               {{"start", Position(where->start, where->begin_offset)},
                {"end", Position(where->end, where->end_offset)}}}};
}

Json DiagnosticToJson(const CheckReport& report, const ReportOptions& options,
                      const Diagnostic& diagnostic) {
  Json notes = Json::array();
  for (const DiagnosticNote& note : diagnostic.notes) {
    notes.push_back(
        {{"message", note.message}, {"location", Location(report, options, note.range)}});
  }
  Json fixes = Json::array();
  for (const FixIt& fix : diagnostic.fixes) {
    Json location = Location(report, options, fix.range);
    if (location.is_null()) continue;  // an edit must say where: drop a broken one
    fixes.push_back({{"location", std::move(location)},
                     {"replacement", fix.replacement},
                     {"safety", fix.safety == FixSafety::kSafe ? "safe" : "suggestion"}});
  }
  return Json{{"severity", SeverityName(diagnostic.severity)},
              {"rule", diagnostic.rule_id},
              {"message", diagnostic.message},
              {"location", Location(report, options, diagnostic.range)},
              {"notes", std::move(notes)},
              {"fixes", std::move(fixes)},
              {"fixable", IsFixable(diagnostic)}};
}

}  // namespace

Json ReportToJson(const CheckReport& report, const ReportOptions& options) {
  Json files = Json::array();
  for (const FileReport& file : report.files) {
    Json diagnostics = Json::array();
    for (const Diagnostic& diagnostic : file.diagnostics) {
      diagnostics.push_back(DiagnosticToJson(report, options, diagnostic));
    }
    files.push_back({{"path", file.file ? DisplayPath(file.file->Name(), options.base_directory)
                                        : std::string()},
                     {"dialect", file.dialect},
                     {"stage", file.stage},
                     {"harness", file.harness},
                     {"target", file.target},
                     {"diagnostics", std::move(diagnostics)}});
  }
  const ReportSummary summary = Summarize(report);
  return Json{{"version", kJsonFormatVersion},
              {"tool", {{"name", "shaderport"}, {"version", options.tool_version}}},
              {"files", std::move(files)},
              {"summary",
               {{"errors", summary.errors},
                {"warnings", summary.warnings},
                {"notes", summary.notes},
                {"filesWithProblems", summary.files_with_problems},
                {"filesChecked", summary.files_checked},
                {"fixable", summary.fixable}}}};
}

std::string FormatJson(const CheckReport& report, const ReportOptions& options) {
  // Invalid UTF-8 in a message or replacement is replaced, never thrown on.
  return ReportToJson(report, options).dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace shaderport
