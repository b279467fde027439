// libFuzzer target for `shaderport port` through the library (driver::PortInput
// in port mode, as driver::RunPort (port_run.h) reaches it through PortFile):
// whenever glslang compiles the input in its own dialect, it compiles the WebGL2
// output too, and the source map stays inside the input. Mutated by token_mutator.cpp.
#include <cstdint>
#include <string>

#include "driver/port/port_file.h"
#include "fuzz_driver_util.h"

namespace {

void Require(bool ok, const char* what) { shaderport::fuzz::Check(ok, "fuzz_port", what); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace shaderport;
  if (size > 16384) return 0;
  const std::string input(reinterpret_cast<const char*>(data), size);
  SourceManager sources;
  driver::PortOptions options;
  options.mode = rule::PortMode::kPort;
  const driver::PortResult result =
      driver::PortInput("fuzz.glsl", driver::ClassifyInputText(input), options, sources);
  if (result.read_failed) return 0;
  // The map leads back to the text as read: a byte order mark dropped, lone CRs as LF.
  const std::string read = *driver::ClassifyInputText(input).text;
  Require(result.map.OriginalSize() == read.size(), "map original size");
  Require(result.map.OutputSize() == result.text.size(), "map output size");
  for (const MapSegment& s : result.map.Segments()) {
    Require(s.original_begin <= s.original_end && s.original_end <= read.size(),
            "map segment inside the input");
  }
  for (const Diagnostic& d : result.diagnostics) {
    Require(fuzz::RangeInside(sources, d.range), "diagnostic range");
  }

  // Past a resource limit nothing is ported: the breach is the finding (docs/limits.md).
  if (result.limit_breached) return 0;
  const driver::DetectedKind kind = driver::DetectKind(read, "fuzz.glsl");
  if (fuzz::ValidationErrors(read, kind, false, sources) != 0) return 0;
  Require(result.converged, "the fixes of a port that compiles did not settle");
  driver::DetectedKind output_kind;
  output_kind.dialect = driver::Dialect::kWebGL2;
  output_kind.stage = result.output_stage;
  Require(fuzz::ValidationErrors(result.text, output_kind, true, sources) == 0,
          "the input compiles but its port does not");
  Require(result.validated, "the library did not validate a port that compiles");
  return 0;
}
