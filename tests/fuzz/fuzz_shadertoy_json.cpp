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
#include "json_mutations.h"

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

// Half of the mutations are structured (json_mutations.h): a member of another
// type, a missing member, a value of the wrong shape, which byte flips seldom make
// in a document that still parses. The other half are libFuzzer's own.
extern "C" size_t LLVMFuzzerMutate(uint8_t* data, size_t size, size_t max_size);
extern "C" size_t LLVMFuzzerCustomMutator(uint8_t* data, size_t size, size_t max_size,
                                          unsigned int seed) {
  std::mt19937_64 random(seed);
  if (random() % 2 == 0) {
    const nlohmann::json document = nlohmann::json::parse(data, data + size, nullptr, false);
    if (!document.is_discarded()) {
      const std::string mutated = shaderport::fuzz::MutateJson(document, random).dump();
      if (mutated.size() <= max_size) {
        std::memcpy(data, mutated.data(), mutated.size());
        return mutated.size();
      }
    }
  }
  return LLVMFuzzerMutate(data, size, max_size);
}
