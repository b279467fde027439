// libFuzzer target for the ShaderToy JSON export reader (`shaderport render` of a
// .json record: driver/render_check/render_multipass.cpp): passes, inputs and
// channels are read, every pass is composed with Common and the site's header and
// given the browser transforms. A channel image that cannot be read stops it just
// before the render, so no GL process is forked per input.
#include <cstdint>
#include <cstring>
#include <random>
#include <string>

#include "driver/render_check/render_multipass.h"
#include "fuzz_check.h"
#include "json_custom_mutator.h"

namespace {

void Require(bool ok, const char* what) {
  shaderport::fuzz::Check(ok, "fuzz_shadertoy_json", what);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace shaderport;
  if (size > 65536) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  SourceManager sources;
  driver::RenderFileOptions options;
  options.channel_images[0] = "/nonexistent/fuzz-stops-before-render.png";
  const driver::RenderFileResult result =
      driver::RenderShaderToyJson("fuzz.json", text, sources, options);
  Require(result.file != nullptr, "the record is registered");
  Require(!result.image, "nothing was rendered");
  for (const Diagnostic& d : result.diagnostics) {
    if (!d.range.Valid()) continue;
    Require(d.range.file < sources.Size(), "diagnostic file");
    Require(d.range.begin <= d.range.end && d.range.end <= sources.Get(d.range.file).Text().size(),
            "diagnostic range");
  }
  return 0;
}
