// The code a document's names are declared and used in, for navigation: the document
// itself, or each pass of a ShaderToy JSON project (positions in the JSON text), plus
// in a ShaderToy folder the common.glsl beside a pass, or every pass beside a
// common.glsl. A pass sees its project's Common (the site compiles Common first);
// passes do not see each other. Each piece is analysed alone by shaderport's front
// end (ShaderToy code as GLSL ES 3.00, as the site compiles it).
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "rule/fix_engine.h"
#include "source/source_file.h"

namespace shaderport::driver::lsp {

// One analysed piece of code and where its ranges are shown.
struct CodeUnit {
  std::string uri;                           // the file the ranges are in
  std::shared_ptr<const std::string> shown;  // that file's text: positions count in it
  std::unique_ptr<SourceFile> file;          // the code; offsets map into `shown`
  std::vector<uint32_t> shown_offsets;       // JSON passes: `shown` offset of each code byte (+1)
  uint32_t shift = 0;                        // plain files: a byte order mark before the code
  int project = 0;                           // units of one project see its Common
  bool common = false;                       // ShaderToy Common
  bool in_document = false;                  // the document asked about (or one of its passes)
  rule::AnalyzedShader shader;

  uint32_t ShownOffset(uint32_t code_offset) const;
  // The code offset of a `shown` offset, when it is inside this unit's code.
  std::optional<uint32_t> CodeOffset(uint32_t shown_offset) const;
  nlohmann::json RangeOf(const SourceRange& range) const;  // an LSP Range in `shown`
  nlohmann::json LocationOf(const SourceRange& range) const;
};

// An open document's text for a path (nothing: read the file from disk).
using OpenTextLookup = std::function<std::optional<std::string>(const std::filesystem::path&)>;

struct ProjectCode {
  std::vector<CodeUnit> units;

  // `path`/`uri`/`text`: the document; other files come from `open_text`, else disk.
  static ProjectCode Of(const std::filesystem::path& path, const std::string& uri,
                        const std::string& text, const OpenTextLookup& open_text);

  // The unit of the document holding byte `offset` of its text, and the code offset.
  std::optional<std::pair<const CodeUnit*, uint32_t>> At(uint32_t offset) const;
  // The Common that `unit` sees (nothing for Common itself or without one).
  const CodeUnit* CommonOf(const CodeUnit& unit) const;
};

}  // namespace shaderport::driver::lsp
