#include "report/sarif_format.h"

#include <algorithm>
#include <map>
#include <string_view>
#include <vector>

#include "diag/rule_catalog.h"
#include "report/docs_links.h"
#include "report/fingerprint.h"
#include "report/source_position.h"

namespace shaderport {
namespace {

using Json = nlohmann::ordered_json;

const char* SarifLevel(Severity severity) {
  switch (severity) {
    case Severity::kError:
      return "error";
    case Severity::kWarning:
      return "warning";
    case Severity::kNote:
      return "note";
  }
  return "error";
}

std::string RuleIdOf(const Diagnostic& diagnostic) {
  return diagnostic.rule_id.empty() ? "unknown" : diagnostic.rule_id;
}

// `path` ('/'-separated) without "." and ".." segments, removed by text as RFC 3986
// resolves a reference: SARIF consumers resolve URIs without the file system, and
// Sarif.Multitool rejects ".." in file URIs (SARIF1002). A ".." above the start of a
// relative path stays; one above the root is dropped.
std::string WithoutDotSegments(std::string_view path) {
  size_t root_size = 0;
  while (root_size < path.size() && root_size < 2 && path[root_size] == '/') ++root_size;
  if (root_size == 0 && path.size() >= 3 && path[1] == ':' && path[2] == '/') root_size = 3;
  std::vector<std::string_view> segments;
  for (size_t at = root_size; at <= path.size();) {
    const size_t slash = std::min(path.find('/', at), path.size());
    const std::string_view segment = path.substr(at, slash - at);
    at = slash + 1;
    if (segment.empty() || segment == ".") continue;
    if (segment != "..") {
      segments.push_back(segment);
    } else if (!segments.empty() && segments.back() != "..") {
      segments.pop_back();
    } else if (root_size == 0) {
      segments.push_back(segment);
    }
  }
  std::string out(path.substr(0, root_size));
  for (size_t i = 0; i < segments.size(); ++i) {
    if (i > 0) out += '/';
    out += segments[i];
  }
  return out;
}

// A zero-width region at the start of a file: where a finding about the whole file
// (or about generated code) points, since consumers want a region (SARIF2017, GitHub).
nlohmann::ordered_json StartOfFileRegion() {
  return {{"startLine", 1}, {"startColumn", 1}, {"endLine", 1}, {"endColumn", 1}};
}

class SarifBuilder {
 public:
  SarifBuilder(const CheckReport& report, const ReportOptions& options)
      : report_(report),
        options_(options),
        base_directory_(WithoutDotSegments(DisplayPath(options.base_directory, ""))) {}

  Json Build() {
    // Rules first: results refer to them by index.
    for (const FileReport& file : report_.files) {
      for (const Diagnostic& diagnostic : file.diagnostics) {
        auto [it, inserted] = levels_.emplace(RuleIdOf(diagnostic), diagnostic.severity);
        if (!inserted && diagnostic.severity > it->second) it->second = diagnostic.severity;
      }
    }
    Json rules = Json::array();
    for (const auto& [id, severity] : levels_) {
      rule_index_[id] = rules.size();
      rules.push_back(RuleToJson(id, severity));
    }
    const auto fingerprints = FingerprintReport(report_, options_.base_directory);
    Json results = Json::array();
    for (size_t f = 0; f < report_.files.size(); ++f) {
      const FileReport& file = report_.files[f];
      for (size_t d = 0; d < file.diagnostics.size(); ++d) {
        results.push_back(ResultToJson(file, file.diagnostics[d], fingerprints[f][d].fingerprint));
      }
    }
    Json driver = {{"name", "shaderport"},
                   {"version", options_.tool_version},
                   {"semanticVersion", options_.tool_version},
                   {"informationUri", options_.information_uri.empty() ? std::string(kRepositoryUri)
                                                                       : options_.information_uri}};
    driver["rules"] = std::move(rules);

    Json run = {{"tool", {{"driver", std::move(driver)}}}};
    if (IsAbsolutePath(base_directory_)) {
      std::string base = FileUri(base_directory_);
      if (base.back() != '/') base += '/';
      run["originalUriBaseIds"] = {{kSarifSourceRoot, {{"uri", base}}}};
    }
    run["results"] = std::move(results);
    run["columnKind"] = "utf16CodeUnits";
    return Json{{"$schema", kSarifSchemaUri}, {"version", "2.1.0"}, {"runs", Json::array({run})}};
  }

 private:
  static std::string FileUri(const std::string& absolute_path) {
    // "C:/x" keeps its drive colon; everything else is percent-encoded.
    if (absolute_path.size() >= 2 && absolute_path[1] == ':') {
      return "file:///" + absolute_path.substr(0, 2) + EncodeUriPath(absolute_path.substr(2));
    }
    return "file://" + EncodeUriPath(absolute_path);
  }

  Json RuleToJson(const std::string& id, Severity severity) const {
    Json rule = {{"id", id}};
    if (const RuleDescription* description = FindRule(id)) {
      rule["shortDescription"] = {{"text", std::string(description->summary)}};
      rule["fullDescription"] = {{"text", std::string(description->help)}};
      rule["help"] = {{"text", std::string(description->help)}};
      const auto& sections = options_.rules_with_sections;
      rule["helpUri"] = RuleHelpUri(id, std::binary_search(sections.begin(), sections.end(), id));
    } else {
      rule["shortDescription"] = {{"text", id}};  // not in the catalog: no docs to point at
    }
    rule["defaultConfiguration"] = {{"level", SarifLevel(severity)}};
    return rule;
  }

  // Relative to %SRCROOT% when the file lies below it, else an absolute file URI;
  // a relative name is taken relative to the base directory.
  Json ArtifactLocation(const SourceFile& file) const {
    std::string path = DisplayPath(file.Name(), "");
    if (!IsAbsolutePath(path) && IsAbsolutePath(base_directory_)) {
      path = base_directory_ + (base_directory_.ends_with('/') ? "" : "/") + path;
    }
    path = DisplayPath(WithoutDotSegments(path), base_directory_);
    if (IsAbsolutePath(path)) return {{"uri", FileUri(path)}};
    return {{"uri", EncodeUriPath(path)}, {"uriBaseId", kSarifSourceRoot}};
  }

  static Json Region(const ResolvedRange& where) {
    return {{"startLine", where.start_utf16.line},
            {"startColumn", where.start_utf16.column},
            {"endLine", where.end_utf16.line},
            {"endColumn", where.end_utf16.column}};
  }

  // A synthetic file (a generated header) is no artifact: point at the checked file.
  // A pass of a JSON project points at its bytes in the JSON document.
  Json PhysicalLocation(const SourceRange& range, const SourceFile* fallback) const {
    const auto where = Resolve(report_.sources, range);
    if (where) {
      if (const auto outer = ResolveInContainer(*where))
        return {{"artifactLocation", ArtifactLocation(*outer->file)}, {"region", Region(*outer)}};
    }
    if (where && !where->file->IsSynthetic()) {
      return {{"artifactLocation", ArtifactLocation(*where->file)}, {"region", Region(*where)}};
    }
    if (fallback == nullptr) return nullptr;
    return {{"artifactLocation", ArtifactLocation(*fallback)}, {"region", StartOfFileRegion()}};
  }

  // The pass of a JSON project ("Buffer A") the finding is in, with the line and
  // column inside the pass's own code, which the JSON region cannot show.
  Json LogicalLocations(const SourceRange& range, const SourceFile* fallback) const {
    const auto where = Resolve(report_.sources, range);
    const SourceFile* file = where ? where->file : fallback;
    const Embedding* embedding = file != nullptr ? file->Embedded() : nullptr;
    if (embedding == nullptr) return nullptr;
    Json logical = {{"name", embedding->logical_name},
                    {"fullyQualifiedName", file->Name()},
                    {"kind", "module"}};
    if (where) {
      logical["properties"] = {{"shaderport/passLine", where->start.line},
                               {"shaderport/passColumn", where->start.column}};
    }
    return Json::array({std::move(logical)});
  }

  Json FixesToJson(const Diagnostic& diagnostic) const {
    // The fix-its of one diagnostic are applied together: one SARIF fix holds them all.
    Json changes = Json::array();
    std::string description;
    for (const FixIt& fix : diagnostic.fixes) {
      const auto where = Resolve(report_.sources, fix.range);
      // A pass of a JSON project: its edits need JSON escaping (`shaderport fix` does it).
      if (!where || where->file->IsSynthetic() || where->file->Embedded() != nullptr) continue;
      Json replacement = {{"deletedRegion", Region(*where)},
                          {"insertedContent", {{"text", fix.replacement}}}};
      Json artifact = ArtifactLocation(*where->file);
      if (!changes.empty() && changes.back()["artifactLocation"] == artifact) {
        changes.back()["replacements"].push_back(std::move(replacement));
      } else {
        changes.push_back({{"artifactLocation", std::move(artifact)},
                           {"replacements", Json::array({std::move(replacement)})}});
      }
      if (fix.safety == FixSafety::kSuggestion) description = "Suggested fix (review it)";
    }
    if (changes.empty()) return Json::array();
    if (description.empty()) description = "Safe fix";
    return Json::array(
        {{{"description", {{"text", description}}}, {"artifactChanges", std::move(changes)}}});
  }

  Json ResultToJson(const FileReport& file, const Diagnostic& diagnostic,
                    const std::string& fingerprint) const {
    const std::string id = RuleIdOf(diagnostic);
    Json result = {{"ruleId", id},
                   {"ruleIndex", rule_index_.at(id)},
                   {"level", SarifLevel(diagnostic.severity)},
                   {"message", {{"text", diagnostic.message}}}};
    Json location = PhysicalLocation(diagnostic.range, file.file);
    result["locations"] = Json::array();
    if (!location.is_null()) {
      Json entry = {{"physicalLocation", location}};
      if (Json logical = LogicalLocations(diagnostic.range, file.file); !logical.is_null())
        entry["logicalLocations"] = std::move(logical);
      result["locations"].push_back(std::move(entry));
    }
    if (!diagnostic.notes.empty()) {
      Json related = Json::array();
      int id_number = 1;
      for (const DiagnosticNote& note : diagnostic.notes) {
        Json entry = {{"id", id_number++}, {"message", {{"text", note.message}}}};
        Json note_location = PhysicalLocation(note.range, nullptr);
        if (!note_location.is_null()) entry["physicalLocation"] = std::move(note_location);
        related.push_back(std::move(entry));
      }
      result["relatedLocations"] = std::move(related);
    }
    Json fixes = FixesToJson(diagnostic);
    if (!fixes.empty()) result["fixes"] = std::move(fixes);
    result["partialFingerprints"] = {{kFingerprintKey, fingerprint}};
    return result;
  }

  const CheckReport& report_;
  const ReportOptions& options_;
  std::string base_directory_;              // '/'-separated, without "." or ".." segments
  std::map<std::string, Severity> levels_;  // sorted by id: the order of rules[]
  std::map<std::string, size_t> rule_index_;
};

}  // namespace

Json ReportToSarif(const CheckReport& report, const ReportOptions& options) {
  return SarifBuilder(report, options).Build();
}

std::string FormatSarif(const CheckReport& report, const ReportOptions& options) {
  return ReportToSarif(report, options).dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace shaderport
