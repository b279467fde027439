#include "validate/precise_pass.h"

#include <atomic>

namespace glslang {
class TIntermediate;
}

namespace shaderport::validate {
namespace {

thread_local bool skip_precise_pass = false;
std::atomic<uint64_t> skipped_precise_passes{0};

}  // namespace

bool CannotSpellPrecise(std::string_view text) {
  return text.find("precise") == std::string_view::npos &&
         text.find("##") == std::string_view::npos && text.find('\\') == std::string_view::npos;
}

PrecisePassSkip::PrecisePassSkip(std::span<const std::string_view> texts)
    : previous_(skip_precise_pass) {
  bool skip = true;
  for (std::string_view text : texts) skip = skip && CannotSpellPrecise(text);
  skip_precise_pass = skip;
}

PrecisePassSkip::~PrecisePassSkip() { skip_precise_pass = previous_; }

uint64_t PrecisePassesSkipped() { return skipped_precise_passes.load(std::memory_order_relaxed); }

#if SHADERPORT_WRAP_PRECISE_PASS

bool PrecisePassCanBeSkipped() { return true; }

// glslang::PropagateNoContraction(const TIntermediate&) by its linker names: the
// link resolves glslang's own call to the wrapper, and __real_ to the original.
void RealPropagateNoContraction(const glslang::TIntermediate& intermediate) asm(
    "__real__ZN7glslang22PropagateNoContractionERKNS_13TIntermediateE");
void WrappedPropagateNoContraction(const glslang::TIntermediate& intermediate) asm(
    "__wrap__ZN7glslang22PropagateNoContractionERKNS_13TIntermediateE");

void WrappedPropagateNoContraction(const glslang::TIntermediate& intermediate) {
  if (skip_precise_pass) {
    skipped_precise_passes.fetch_add(1, std::memory_order_relaxed);
    return;
  }
  RealPropagateNoContraction(intermediate);
}

#else

bool PrecisePassCanBeSkipped() { return false; }

#endif

}  // namespace shaderport::validate
