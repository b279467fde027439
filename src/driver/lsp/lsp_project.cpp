#include "driver/lsp/lsp_project.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <sstream>

#include "base/limits.h"
#include "driver/check_projects.h"
#include "driver/dialect.h"
#include "driver/lsp/lsp_check.h"
#include "driver/lsp/lsp_text.h"
#include "driver/project/json_project_reader.h"

namespace shaderport::driver::lsp {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";

// A file beside the document: the editor's text when it is open, else the disk's
// (nothing when unreadable or over the input limit).
std::optional<std::string> TextOf(const fs::path& path, const OpenTextLookup& open_text) {
  if (std::optional<std::string> open = open_text(path)) return open;
  std::error_code error;
  const auto size = fs::file_size(path, error);
  if (error || size > limits::kMaxFileBytes) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// A plain GLSL file as one unit, analysed as its dialect and stage.
CodeUnit PlainUnit(const fs::path& path, std::string uri, std::shared_ptr<const std::string> text,
                   bool in_document) {
  CodeUnit unit;
  unit.uri = std::move(uri);
  unit.shift = text->starts_with(kByteOrderMark) ? 3 : 0;
  std::string body = text->substr(unit.shift);
  const DetectedKind kind = DetectKind(body, path);
  unit.shown = std::move(text);
  unit.file = std::make_unique<SourceFile>(0, path.string(), std::move(body));
  unit.common = path.filename() == "common.glsl";
  unit.in_document = in_document;
  const int version = kind.dialect == Dialect::kWebGL1 ? 100 : 300;
  unit.shader = rule::AnalyzePlain(*unit.file, version, kind.stage);
  return unit;
}

// Every pass of every project of a JSON document, positions in the document.
void AddJsonPasses(const fs::path& path, const std::string& uri,
                   const std::shared_ptr<const std::string>& text, ProjectCode& code) {
  const project::ProjectDocument read = path.extension() == ".jsonl"
                                            ? project::ReadShaderToyJsonLines(*text)
                                            : project::ReadShaderToyJson(*text);
  for (size_t p = 0; p < read.projects.size(); ++p) {
    for (const project::ProjectPass& pass : read.projects[p].passes) {
      if (pass.origin.document_offsets.size() != pass.code.size() + 1) continue;
      CodeUnit unit;
      unit.uri = uri;
      unit.shown = text;
      unit.shown_offsets = pass.origin.document_offsets;
      unit.file = std::make_unique<SourceFile>(0, path.string() + "#" + pass.name, pass.code);
      unit.project = static_cast<int>(p);
      unit.common = pass.kind == model::PassKind::kCommon;
      unit.in_document = true;
      unit.shader = rule::AnalyzePlain(*unit.file, 300, model::Stage::kFragment);
      code.units.push_back(std::move(unit));
    }
  }
}

// The ShaderToy folder around a plain document: its common.glsl, or (for common.glsl)
// the passes beside it, in name order.
void AddFolderFiles(const fs::path& path, const OpenTextLookup& open_text, ProjectCode& code) {
  const fs::path directory = fs::absolute(path).parent_path();
  std::vector<fs::path> others;
  if (path.filename() == "common.glsl") {
    std::error_code error;
    for (const fs::directory_entry& entry : fs::directory_iterator(directory, error)) {
      const fs::path& other = entry.path();
      if (other.extension() == ".glsl" && other.filename() != "common.glsl" &&
          entry.is_regular_file(error)) {
        others.push_back(other);
      }
    }
    std::sort(others.begin(), others.end());
  } else {
    others.push_back(directory / "common.glsl");
  }
  for (const fs::path& other : others) {
    std::optional<std::string> text = TextOf(other, open_text);
    if (!text) continue;
    code.units.push_back(PlainUnit(other, UriOfPath(other),
                                   std::make_shared<const std::string>(std::move(*text)), false));
  }
}

}  // namespace

uint32_t CodeUnit::ShownOffset(uint32_t code_offset) const {
  if (shown_offsets.empty()) return code_offset + shift;
  return shown_offsets[std::min<size_t>(code_offset, shown_offsets.size() - 1)];
}

std::optional<uint32_t> CodeUnit::CodeOffset(uint32_t shown_offset) const {
  if (shown_offsets.empty()) {
    if (shown_offset < shift || shown_offset - shift > file->Text().size()) return std::nullopt;
    return shown_offset - shift;
  }
  if (shown_offset < shown_offsets.front() || shown_offset > shown_offsets.back()) {
    return std::nullopt;
  }
  // The first code byte at or after the offset (an escape sequence is several bytes).
  const auto at = std::lower_bound(shown_offsets.begin(), shown_offsets.end(), shown_offset);
  return static_cast<uint32_t>(at - shown_offsets.begin());
}

Json CodeUnit::RangeOf(const SourceRange& range) const {
  return {{"start", ToJson(PositionOf(*shown, ShownOffset(range.begin)))},
          {"end", ToJson(PositionOf(*shown, ShownOffset(range.end)))}};
}

Json CodeUnit::LocationOf(const SourceRange& range) const {
  return {{"uri", uri}, {"range", RangeOf(range)}};
}

ProjectCode ProjectCode::Of(const fs::path& path, const std::string& uri, const std::string& text,
                            const OpenTextLookup& open_text) {
  ProjectCode code;
  // As check, which reports such a file as input/too-large without reading its code.
  if (text.size() > limits::kMaxFileBytes) return code;
  auto shown = std::make_shared<const std::string>(text);
  if (IsProjectDocument(path)) {
    AddJsonPasses(path, uri, shown, code);
    return code;
  }
  code.units.push_back(PlainUnit(path, uri, shown, true));
  // Only a ShaderToy pass has a Common; a .frag/.vert of a WebGL page does not.
  const DetectedKind kind = DetectKind(text, path);
  if (kind.dialect == Dialect::kShaderToy && path.has_parent_path()) {
    AddFolderFiles(path, open_text, code);
  }
  return code;
}

std::optional<std::pair<const CodeUnit*, uint32_t>> ProjectCode::At(uint32_t offset) const {
  for (const CodeUnit& unit : units) {
    if (!unit.in_document) continue;
    if (const std::optional<uint32_t> at = unit.CodeOffset(offset)) {
      return std::pair(&unit, *at);
    }
  }
  return std::nullopt;
}

const CodeUnit* ProjectCode::CommonOf(const CodeUnit& unit) const {
  if (unit.common) return nullptr;
  for (const CodeUnit& other : units) {
    if (other.common && other.project == unit.project) return &other;
  }
  return nullptr;
}

}  // namespace shaderport::driver::lsp
