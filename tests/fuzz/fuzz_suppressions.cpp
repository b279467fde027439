// libFuzzer target for suppression comments (driver/suppress): the input is read
// as one comment, then as a file whose comments suppress diagnostics placed on
// each of its lines. Pattern offsets point at the pattern's bytes, suppressing
// only removes diagnostics, and what is added stays inside the file.
#include <algorithm>
#include <cstdint>
#include <string>

#include "driver/suppress/suppression_comment.h"
#include "driver/suppress/suppressions.h"
#include "fuzz_check.h"
#include "glsl/lex/lexer.h"
#include "source/source_manager.h"

namespace {

void Require(bool ok, const char* what) { shaderport::fuzz::Check(ok, "fuzz_suppressions", what); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace shaderport;
  if (size > 65536) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);

  if (const auto directive = driver::ParseSuppressionComment(text)) {
    for (const driver::RulePatternSpan& p : directive->patterns) {
      Require(p.offset <= text.size() && p.pattern.size() <= text.size() - p.offset,
              "pattern offset inside the comment");
      Require(text.compare(p.offset, p.pattern.size(), p.pattern) == 0,
              "pattern offset points at the pattern");
    }
  }

  SourceManager sources;
  const SourceFile& file = sources.Add("fuzz.frag", text);
  const glsl::LexedFile lexed = glsl::Lex(file);
  // One diagnostic per line (capped), of rules the suppressions may name.
  DiagnosticList diagnostics;
  const char* rules[] = {"glslang/syntax", "webgl/no-precision", "suppression/unused"};
  const uint32_t lines = std::min<uint32_t>(file.LineCount(), 256);
  for (uint32_t line = 1; line <= lines; ++line) {
    const uint32_t begin = file.LineStart(line);
    const uint32_t end = begin + static_cast<uint32_t>(file.LineText(line).size());
    diagnostics.push_back(
        MakeDiagnostic(Severity::kWarning, rules[line % 3], {file.Id(), begin, end}, "fuzz"));
  }
  const size_t before = diagnostics.size();
  driver::ApplySuppressions(file, lexed, diagnostics);
  size_t kept = 0;
  for (const Diagnostic& d : diagnostics) {
    Require(d.range.file == file.Id() && d.range.begin <= d.range.end && d.range.end <= text.size(),
            "diagnostic inside the file");
    if (d.message == "fuzz") ++kept;
  }
  Require(kept <= before, "suppressing added diagnostics");
  return 0;
}
