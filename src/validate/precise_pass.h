// glslang runs its `precise` propagation (PropagateNoContraction) after every parse:
// a walk of the whole tree that builds a string per assignment, about a twentieth of
// `check`'s instructions. Only the keyword `precise` can make it change anything, and
// validation never reads what it changes, so `check` skips it for texts that cannot
// spell that keyword. The link wraps glslang's function (-Wl,--wrap, CMakeLists.txt);
// every parse outside a PrecisePassSkip scope runs the real pass.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace shaderport::validate {

// True when glslang cannot scan the keyword `precise` out of `text`: the word is not
// in it, and no token pasting (`##`) or line continuation could assemble it.
bool CannotSpellPrecise(std::string_view text);

// While alive, glslang parses on this thread skip the pass when every text of
// `texts` CannotSpellPrecise. Scopes nest; the previous setting comes back.
class PrecisePassSkip {
 public:
  explicit PrecisePassSkip(std::span<const std::string_view> texts);
  ~PrecisePassSkip();
  PrecisePassSkip(const PrecisePassSkip&) = delete;
  PrecisePassSkip& operator=(const PrecisePassSkip&) = delete;

 private:
  bool previous_;
};

// Whether this build wraps glslang's pass at all (see CMakeLists.txt).
bool PrecisePassCanBeSkipped();

// Passes skipped in this process so far (for tests and profiles).
uint64_t PrecisePassesSkipped();

}  // namespace shaderport::validate
