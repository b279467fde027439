#include "driver/lsp/lsp_check.h"

#include <algorithm>
#include <utility>

#include "driver/check_pipeline.h"
#include "driver/check_projects.h"
#include "driver/lsp/lsp_text.h"
#include "driver/port/port_file.h"
#include "driver/read_input.h"
#include "model/shipped_dialects.h"
#include "report/docs_links.h"

namespace shaderport::driver::lsp {
namespace {

using Json = nlohmann::json;

int SeverityCode(Severity severity) {
  switch (severity) {
    case Severity::kError:
      return 1;
    case Severity::kWarning:
      return 2;
    case Severity::kNote:
      break;
  }
  return 3;  // Information
}

// Offsets into the document's own text: a pass of a JSON project sits inside the
// document (its embedding), and a byte order mark was taken off what check read.
class DocumentPositions {
 public:
  DocumentPositions(const std::string& text, uint32_t shift) : text_(text), shift_(shift) {}

  // Nothing for a range outside the document.
  std::optional<Json> Range(const SourceManager& sources, const SourceRange& range,
                            FileId document) const {
    if (!range.Valid()) return std::nullopt;
    const SourceFile& file = sources.Get(range.file);
    uint32_t begin = range.begin;
    uint32_t end = range.end;
    if (const Embedding* embedding = file.Embedded()) {
      begin = embedding->ContainerOffset(begin);
      end = embedding->ContainerOffset(end);
    } else if (range.file != document) {
      return std::nullopt;
    }
    return Json{{"start", ToJson(PositionOf(text_, begin + shift_))},
                {"end", ToJson(PositionOf(text_, end + shift_))}};
  }

 private:
  const std::string& text_;
  uint32_t shift_;
};

// An old name the harness renamed (ShaderToy's iGlobalTime, now iTime): editors
// strike it through as deprecated code.
bool IsRenamedHarnessName(const std::string& harness, std::string_view text) {
  const model::HarnessDialect* dialect = model::FindBuiltinDialect(harness);
  if (dialect == nullptr || text.empty()) return false;
  return std::any_of(dialect->renames.begin(), dialect->renames.end(),
                     [&](const auto& rename) { return rename.first == text; });
}

Json WholeFileRange() { return {{"start", ToJson({0, 0})}, {"end", ToJson({0, 0})}}; }

}  // namespace

std::string UriOfPath(const std::filesystem::path& path) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string uri = "file://";
  for (const unsigned char c : std::filesystem::absolute(path).lexically_normal().string()) {
    const bool plain =
        std::isalnum(c) != 0 || c == '/' || c == '-' || c == '_' || c == '.' || c == '~';
    if (plain) {
      uri += static_cast<char>(c);
    } else {
      uri += '%';
      uri += kHex[c >> 4];
      uri += kHex[c & 15];
    }
  }
  return uri;
}

DocumentCheck CheckDocument(const std::filesystem::path& path, std::string_view uri,
                            const std::string& text,
                            const std::vector<std::string>& rules_with_sections,
                            const DocumentCheckSettings& settings) {
  CheckOptions options;
  options.target = settings.target;
  options.fail_on = settings.fail_on;
  options.render = settings.render;
  options.jobs = 1;
  options.force_exclude = false;  // an open file is checked even when the config skips it
  InputText input = ClassifyInputText(text);
  const uint32_t shift = input.byte_order_mark ? 3 : 0;
  options.in_memory = CheckOptions::InMemoryFile{path, std::move(input)};
  CheckRun run = RunCheck(options);
  const SourceManager& sources = *run.sources;
  const DocumentPositions positions(text, shift);
  DocumentCheck checked;
  checked.rendered = settings.render;
  checked.fails = run.failed;
  std::vector<DocumentFinding>& findings = checked.findings;
  for (const FileReport& report : run.report.files) {
    if (report.file == nullptr) continue;
    if (checked.decision.empty() && !report.dialect.empty()) {
      checked.decision = report.dialect + " " + report.stage + " shader" +
                         (report.harness.empty() ? "" : ", harness " + report.harness) +
                         ", target " + report.target;
      checked.dialect = report.dialect;
      checked.stage = report.stage;
      checked.harness = report.harness;
      checked.target = report.target;
      for (size_t at = 0; at < report.channels.size();) {
        const size_t space = std::min(report.channels.find(' ', at), report.channels.size());
        checked.channels.push_back(report.channels.substr(at, space - at));
        at = space + 1;
      }
      checked.fail_on = report.fail_on;
    }
    const FileId document = report.file->Id();
    for (const Diagnostic& d : report.diagnostics) {
      std::optional<Json> range = positions.Range(sources, d.range, document);
      if (!range && d.range.Valid()) continue;  // in another file (Common): shown there
      DocumentFinding finding;
      Json& out = finding.diagnostic;
      out = {{"range", range ? *range : WholeFileRange()},
             {"severity", SeverityCode(d.severity)},
             {"code", d.rule_id},
             {"source", "shaderport"},
             {"message", d.message}};
      const bool documented =
          std::binary_search(rules_with_sections.begin(), rules_with_sections.end(), d.rule_id);
      out["codeDescription"] = {{"href", RuleHelpUri(d.rule_id, documented)}};
      Json related = Json::array();
      for (const DiagnosticNote& note : d.notes) {
        std::optional<Json> where = positions.Range(sources, note.range, document);
        if (!where) continue;
        related.push_back({{"location", {{"uri", std::string(uri)}, {"range", *where}}},
                           {"message", note.message}});
      }
      if (!related.empty()) out["relatedInformation"] = std::move(related);
      finding.edits = Json::array();
      finding.safe = !d.fixes.empty();
      for (const FixIt& fix : d.fixes) {
        std::optional<Json> where = positions.Range(sources, fix.range, document);
        if (!where) {
          finding.edits = Json::array();  // an edit elsewhere: the set is not offered
          break;
        }
        finding.edits.push_back({{"range", *where}, {"newText", fix.replacement}});
        finding.safe = finding.safe && fix.safety == FixSafety::kSafe;
      }
      // Editors fade unnecessary code: a suppression comment that silences nothing.
      if (d.rule_id == "suppression/unused") out["tags"] = Json::array({1});
      if (d.range.Valid() && d.range.end <= sources.Get(d.range.file).Text().size() &&
          IsRenamedHarnessName(
              report.harness,
              sources.Get(d.range.file).Text().substr(d.range.begin, d.range.Size()))) {
        out["tags"] = Json::array({2});
      }
      out["data"] = {{"fixable", IsFixable(d)}};
      findings.push_back(std::move(finding));
    }
  }
  return checked;
}

namespace {

// The document through the fix engine in `mode` ("" when nothing is to be written).
std::string Rewrite(const std::filesystem::path& path, const std::string& text,
                    rule::PortMode mode) {
  if (IsProjectDocument(path)) return "";  // projects are rewritten tab by tab
  SourceManager sources;
  PortOptions options;
  options.mode = mode;
  PortResult result = PortInput(path, ClassifyInputText(text), options, sources);
  if (!result.HasOutput() || !result.Changed()) return "";
  // As `port` writes nothing that does not compile, neither does the editor.
  if (mode == rule::PortMode::kPort && !result.validated) return "";
  return result.byte_order_mark ? "\xEF\xBB\xBF" + result.text : result.text;
}

}  // namespace

std::string FixDocument(const std::filesystem::path& path, const std::string& text) {
  return Rewrite(path, text, rule::PortMode::kFix);
}

std::string PortDocument(const std::filesystem::path& path, const std::string& text) {
  return Rewrite(path, text, rule::PortMode::kPort);
}

}  // namespace shaderport::driver::lsp
