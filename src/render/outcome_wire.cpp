#include "render/outcome_wire.h"

#include <cstring>

#include "render/wire_codec.h"

namespace shaderport::render {
namespace {

using wire::Put;
using wire::PutString;
using wire::Reader;

constexpr uint32_t kMagic = 0x53505232;  // "SPR2"
constexpr uint32_t kMaxStrings = 1024;

}  // namespace

std::string EncodeOutcome(const RenderOutcome& outcome) {
  std::string out;
  Put(out, kMagic);
  Put(out, static_cast<uint8_t>(outcome.status));
  PutString(out, outcome.message);
  PutString(out, outcome.vertex_log);
  PutString(out, outcome.fragment_log);
  PutString(out, outcome.link_log);
  Put(out, static_cast<int32_t>(outcome.failed_pass));
  Put(out, static_cast<uint32_t>(outcome.gl_errors.size()));
  for (const std::string& error : outcome.gl_errors) PutString(out, error);
  Put(out, outcome.max_loop_iterations);
  Put(out, outcome.loop_capped_pixels);
  Put(out, outcome.unassigned_output_pixels);
  Put(out, outcome.width);
  Put(out, outcome.height);
  Put(out, static_cast<uint64_t>(outcome.pixels.size()));
  out.append(reinterpret_cast<const char*>(outcome.pixels.data()),
             outcome.pixels.size() * sizeof(float));
  return out;
}

std::optional<RenderOutcome> DecodeOutcome(const std::string& bytes) {
  Reader in{bytes};
  RenderOutcome outcome;
  uint32_t magic = 0;
  uint8_t status = 0;
  uint32_t errors = 0;
  if (!in.Get(magic) || magic != kMagic || !in.Get(status) ||
      status > static_cast<uint8_t>(RenderStatus::kInternal) || !in.GetString(outcome.message) ||
      !in.GetString(outcome.vertex_log) || !in.GetString(outcome.fragment_log) ||
      !in.GetString(outcome.link_log) || !in.Get(outcome.failed_pass) || !in.Get(errors) ||
      errors > kMaxStrings) {
    return std::nullopt;
  }
  outcome.status = static_cast<RenderStatus>(status);
  outcome.gl_errors.resize(errors);
  for (std::string& error : outcome.gl_errors) {
    if (!in.GetString(error)) return std::nullopt;
  }
  if (!in.Get(outcome.max_loop_iterations) || !in.Get(outcome.loop_capped_pixels) ||
      !in.Get(outcome.unassigned_output_pixels)) {
    return std::nullopt;
  }
  uint64_t count = 0;
  if (!in.Get(outcome.width) || !in.Get(outcome.height) || !in.Get(count) ||
      count != uint64_t{outcome.width} * outcome.height * 4 ||
      (bytes.size() - in.at) != count * sizeof(float)) {
    return std::nullopt;
  }
  outcome.pixels.resize(count);
  // A failed render sends no pixels, and memcpy must not see the empty vector's null data.
  if (count > 0) std::memcpy(outcome.pixels.data(), bytes.data() + in.at, count * sizeof(float));
  return outcome;
}

}  // namespace shaderport::render
