#include "validate/precise_pass.h"

#include <atomic>
#include <string>

#include "glsl/lex/lex_chars.h"

namespace glslang {
class TIntermediate;
}

namespace shaderport::validate {
namespace {

thread_local bool skip_precise_pass = false;
std::atomic<uint64_t> skipped_precise_passes{0};

// `text` with its line continuations (a backslash right before "\n", "\r\n" or "\r")
// removed, as glslang joins lines before it scans words.
std::string JoinContinuedLines(std::string_view text) {
  std::string joined;
  joined.reserve(text.size());
  for (size_t i = 0; i < text.size(); ++i) {
    if (const size_t continuation = glsl::ContinuationLength(text, i)) {
      i += continuation - 1;
      continue;
    }
    joined += text[i];
  }
  return joined;
}

// Whether `word` occurs where glslang could scan it as a token of its own: not after a
// letter or '_' and not before a letter, digit or '_'. A digit before it still counts
// ("1precise" scans as 1 and precise), so this errs towards running the pass.
bool MayHoldWord(std::string_view text, std::string_view word) {
  for (size_t at = text.find(word); at != std::string_view::npos; at = text.find(word, at + 1)) {
    const size_t after = at + word.size();
    const bool joined_before = at > 0 && glsl::IsIdentifierStart(text[at - 1]);
    const bool joined_after = after < text.size() && glsl::IsIdentifierChar(text[after]);
    if (!joined_before && !joined_after) return true;
  }
  return false;
}

}  // namespace

bool CannotSpellPrecise(std::string_view text) {
  // Token pasting can assemble the word from any pieces.
  if (text.find("##") != std::string_view::npos) return false;
  if (text.find('\\') == std::string_view::npos) return !MayHoldWord(text, "precise");
  return !MayHoldWord(JoinContinuedLines(text), "precise");
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
