// libFuzzer target for `shaderport fix` through the library (driver::PortInput in
// fix mode, as driver::RunFixOnText calls it for --stdin): fixing twice
// changes nothing, the fixed text never gets more glslang errors than the input,
// and the source map leads every byte of the result back inside the input
// (copied bytes unchanged). Mutated by token_mutator.cpp.
#include <cstdint>
#include <string>

#include "driver/port/port_file.h"
#include "fuzz_driver_util.h"

namespace {

using shaderport::fuzz::Check;

void Require(bool ok, const char* what) { Check(ok, "fuzz_fix", what); }

shaderport::driver::PortResult Fix(const std::string& text, shaderport::SourceManager& sources) {
  shaderport::driver::PortOptions options;
  options.mode = shaderport::rule::PortMode::kFix;
  return shaderport::driver::PortInput("fuzz.glsl", shaderport::driver::ClassifyInputText(text),
                                       options, sources);
}

void CheckMap(const shaderport::SourceMap& map, const std::string& input,
              const std::string& output) {
  Require(map.OriginalSize() == input.size(), "map original size");
  Require(map.OutputSize() == output.size(), "map output size");
  uint32_t next = 0;
  for (const shaderport::MapSegment& s : map.Segments()) {
    Require(s.output_begin == next, "map segments cover the output in order");
    next = s.output_begin + s.length;
    Require(s.original_begin <= s.original_end && s.original_end <= input.size(),
            "map segment inside the input");
    if (!s.inserted) {
      Require(s.original_end - s.original_begin == s.length, "copied segment length");
      Require(output.compare(s.output_begin, s.length, input, s.original_begin, s.length) == 0,
              "copied segment equals the input");
    }
  }
  Require(next == output.size(), "map covers the output");
}

void CheckRanges(const shaderport::SourceManager& sources,
                 const shaderport::DiagnosticList& diagnostics) {
  for (const auto& d : diagnostics) {
    Require(shaderport::fuzz::RangeInside(sources, d.range), "diagnostic range");
    for (const auto& n : d.notes) Require(shaderport::fuzz::RangeInside(sources, n.range), "note");
    for (const auto& f : d.fixes) Require(shaderport::fuzz::RangeInside(sources, f.range), "fix");
  }
}

bool Fighting(const shaderport::DiagnosticList& diagnostics) {
  for (const auto& d : diagnostics) {
    if (d.rule_id == "internal/error") return true;
  }
  return false;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace shaderport;
  // Kept small: every input goes through the rules and glslang several times.
  if (size > 16384) return 0;
  const std::string input(reinterpret_cast<const char*>(data), size);
  SourceManager sources;
  const driver::PortResult first = Fix(input, sources);
  if (first.read_failed) return 0;
  // The map leads back to the text as read: a byte order mark dropped, lone CRs as LF.
  const std::string read = *driver::ClassifyInputText(input).text;
  CheckMap(first.map, read, first.text);
  CheckRanges(sources, first.diagnostics);
  CheckRanges(sources, first.fixed);
  if (!first.Changed()) return 0;

  const driver::DetectedKind kind = driver::DetectKind(read, "fuzz.glsl");
  Require(fuzz::ValidationErrors(first.text, kind, false, sources) <=
              fuzz::ValidationErrors(read, kind, false, sources),
          "the fixed text has more glslang errors than the input");

  // Rules that still wanted edits after the last round say so; then a second fix may go on.
  if (Fighting(first.diagnostics)) return 0;
  const driver::PortResult second = Fix(first.text, sources);
  Require(second.text == first.text, "fix(fix(x)) != fix(x)");
  return 0;
}
