#include "driver/front_end.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace shaderport::driver {
namespace {

glsl::ParseResult ParseUnit(const std::vector<const SourceFile*>& files, int forced_version,
                            bool hw_performance, glsl::PreprocessResult& preprocessed,
                            uint32_t max_identifier_length = 0,
                            std::vector<const glsl::LexedFile*> lexed = {},
                            std::vector<int64_t> first_lines = {}) {
  glsl::PreprocessOptions options;
  options.max_identifier_length = max_identifier_length;
  options.lexed = std::move(lexed);
  options.first_lines = std::move(first_lines);
  // The site defines HW_PERFORMANCE for every pass (not for the Common tab alone).
  if (hw_performance) options.predefined = {"HW_PERFORMANCE=1"};
  preprocessed = glsl::Preprocess(files, options);
  glsl::ParseOptions parse_options;
  parse_options.version = forced_version != 0 ? forced_version : preprocessed.version.number;
  return glsl::Parse(preprocessed, parse_options);
}

// The header is parsed once per run and channel types, not once per file: it was
// about a tenth of the front end's work on a short pass. Only its declarations are
// read (as predeclared symbols, without nodes or ranges), so sharing one tree and
// one generated file between files changes nothing they report.
std::shared_ptr<const glsl::ParseResult> ShaderToyHeaderTree(model::PassKind pass,
                                                             const model::ChannelKinds& channels,
                                                             SourceManager& sources) {
  // The Common tab alone sees its own, shorter header; every pass the Image pass's.
  std::string text = validate::ShaderToyHeader(
      pass == model::PassKind::kCommon ? pass : model::PassKind::kImage, channels);
  std::string key = "front-end:shadertoy-header:" + text;
  return std::static_pointer_cast<const glsl::ParseResult>(sources.Memo(key, [&] {
    const SourceFile& header = sources.Add("<shadertoy-header>", std::move(text), true);
    glsl::PreprocessResult header_tokens;
    return std::make_shared<const glsl::ParseResult>(
        ParseUnit({&header}, glsl::kEssl300, true, header_tokens));
  }));
}

// A harness's declarations, parsed once per run and text (see ShaderToyHeaderTree).
std::shared_ptr<const glsl::ParseResult> HarnessHeaderTree(std::string_view text, int version,
                                                           SourceManager& sources) {
  std::string key = "front-end:harness-header:" + std::string(text);
  return std::static_pointer_cast<const glsl::ParseResult>(sources.Memo(key, [&] {
    const SourceFile& header = sources.Add("<harness-header>", std::string(text), true);
    glsl::PreprocessResult header_tokens;
    return std::make_shared<const glsl::ParseResult>(
        ParseUnit({&header}, version, false, header_tokens));
  }));
}

void Append(DiagnosticList& to, const DiagnosticList& from) {
  to.insert(to.end(), from.begin(), from.end());
}

}  // namespace

FrontEndResult RunFrontEnd(const SourceFile& file, const SourceFile* common,
                           const DetectedKind& kind, SourceManager& sources,
                           const FrontEndOptions& options) {
  return RunFrontEnd(file, glsl::Lex(file), common, kind, sources, options);
}

FrontEndResult RunFrontEnd(const SourceFile& file, glsl::LexedFile lexed, const SourceFile* common,
                           const DetectedKind& kind, SourceManager& sources,
                           const FrontEndOptions& options) {
  FrontEndResult result;
  result.lexed = std::move(lexed);
  const bool shadertoy = kind.dialect == Dialect::kShaderToy;
  std::vector<const SourceFile*> files;
  std::vector<const glsl::LexedFile*> file_tokens;
  if (shadertoy && common != nullptr) {
    files.push_back(common);
    file_tokens.push_back(nullptr);
  }
  files.push_back(&file);
  file_tokens.push_back(&result.lexed);
  // ShaderToy code is compiled by the site as GLSL ES 3.00 behind its header, a
  // harness's code as its prelude says.
  const int forced_version = shadertoy ? glsl::kEssl300 : options.harness_version;
  // ShaderToy's parts are one text behind the site's header, and __LINE__ counts so.
  std::vector<int64_t> first_lines;
  if (shadertoy) {
    first_lines = validate::ShaderToyFirstLines(kind.pass, common);
    for (size_t i = 0; i < files.size(); ++i) {
      result.first_lines.emplace_back(files[i]->Id(), first_lines[i]);
    }
  }
  const bool hw_performance = shadertoy && kind.pass != model::PassKind::kCommon;
  result.parsed =
      ParseUnit(files, forced_version, hw_performance, result.preprocessed,
                options.max_identifier_length, std::move(file_tokens), std::move(first_lines));
  Append(result.diagnostics, result.preprocessed.diagnostics);
  Append(result.diagnostics, result.parsed.diagnostics);

  if (!options.analyze) return result;
  glsl::AnalyzeOptions analyze;
  analyze.version = forced_version != 0 ? forced_version : result.preprocessed.version.number;
  analyze.stage = kind.stage;
  if (shadertoy) {
    result.header = ShaderToyHeaderTree(kind.pass, options.channels, sources);
    analyze.header = &result.header->tree;
  } else if (!options.harness_header.empty()) {
    result.header = HarnessHeaderTree(options.harness_header, analyze.version, sources);
    analyze.header = &result.header->tree;
  }
  result.model = glsl::Analyze(result.parsed.tree, analyze);
  return result;
}

}  // namespace shaderport::driver
