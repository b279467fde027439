// libFuzzer target for the GLSL front end: arbitrary bytes must lex back to
// themselves, preprocess without crashing, and yield only ranges inside files.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "base/limits.h"
#include "glsl/lex/lexer.h"
#include "glsl/lex/preprocessor.h"
#include "glsl/syntax/parser.h"
#include "glsl/syntax/visit.h"
#include "source/source_manager.h"

namespace {

using shaderport::SourceManager;
using shaderport::SourceRange;

void Check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "fuzz_frontend: %s\n", what);
    std::abort();
  }
}

void CheckRange(const SourceManager& sources, SourceRange r, const char* what) {
  if (!r.Valid()) return;
  Check(r.file < sources.Size(), what);
  Check(r.begin <= r.end && r.end <= sources.Get(r.file).Text().size(), what);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace shaderport;
  using namespace shaderport::glsl;
  if (size > limits::kMaxFileBytes) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);

  SourceManager sources;
  // A form feed + "@@" splits the input into files of one translation unit
  // (as ShaderToy's Common pass and a pass are), so macros cross files.
  std::vector<const SourceFile*> files;
  size_t begin = 0;
  while (files.size() < 3) {
    const size_t split = text.find("\f@@", begin);
    if (split == std::string::npos) break;
    files.push_back(&sources.Add("part.glsl", text.substr(begin, split - begin)));
    begin = split + 3;
  }
  files.push_back(&sources.Add("fuzz.glsl", text.substr(begin)));

  for (const SourceFile* file : files) {
    const LexedFile lexed = Lex(*file);
    Check(Reconstruct(*file, lexed) == file->Text(), "lexer round trip");
    Check(!lexed.tokens.empty() && lexed.tokens.back().kind == TokenKind::kEndOfFile,
          "lexer end of file");
    for (const Token& t : lexed.tokens) {
      Check(t.begin <= t.end && t.end <= file->Text().size(), "token range");
      Check(t.trivia_begin <= t.trivia_end && t.trivia_end <= lexed.trivia.size(), "trivia");
    }
    for (const auto& d : lexed.diagnostics) CheckRange(sources, d.range, "lexer diagnostic");
  }

  PreprocessOptions options;
  options.predefined = {"HW_PERFORMANCE=1"};
  const PreprocessResult pp = Preprocess(files, options);
  Check(!pp.tokens.empty() && pp.tokens.back().kind == TokenKind::kEndOfFile, "pp end of file");
  for (const PpToken& t : pp.tokens) {
    CheckRange(sources, t.spelling, "token spelling");
    CheckRange(sources, t.expansion, "token expansion");
    Check(t.macro_use == kNoMacroUse || t.macro_use < pp.macro_uses.size(), "token macro use");
  }
  for (size_t i = 0; i < pp.macro_uses.size(); ++i) {
    const MacroUse& use = pp.macro_uses[i];
    CheckRange(sources, use.use, "macro use");
    CheckRange(sources, use.definition, "macro definition");
    Check(use.parent == kNoMacroUse || use.parent < i, "macro use parent");
  }
  for (const auto& r : pp.inactive_regions) CheckRange(sources, r, "inactive region");
  for (const auto& e : pp.extensions) CheckRange(sources, e.range, "extension");
  for (const auto& p : pp.pragmas) CheckRange(sources, p.range, "pragma");
  CheckRange(sources, pp.version.range, "version");
  for (const auto& d : pp.diagnostics) {
    CheckRange(sources, d.range, "diagnostic");
    for (const auto& n : d.notes) CheckRange(sources, n.range, "diagnostic note");
  }
  Check(pp.diagnostics.size() <= limits::kMaxDiagnosticsPerFile + 1, "diagnostic cap");

  (void)DumpPpTokens(pp, sources);

  // The parser: every node lies inside the files, and the tree is well formed
  // (VisitPreorder reaches every node once: no cycles, no sharing).
  glsl::ParseOptions parse_options;
  parse_options.version = pp.version.number;
  const glsl::ParseResult parsed = glsl::Parse(pp, parse_options);
  std::vector<bool> seen(parsed.tree.NodeCount(), false);
  glsl::VisitPreorder(parsed.tree, [&](const glsl::Node& node, uint32_t /*depth*/) {
    Check(node.id < seen.size() && !seen[node.id], "each node reached once");
    seen[node.id] = true;
    if (node.range.Valid()) CheckRange(sources, node.range, "syntax node");
    return true;
  });
  for (const auto& d : parsed.diagnostics) CheckRange(sources, d.range, "parser diagnostic");
  (void)DumpAst(parsed.tree, sources);
  return 0;
}
