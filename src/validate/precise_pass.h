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

// True when glslang cannot scan the keyword `precise` out of `text`: the word does not
// stand alone in it once continued lines are joined ("imprecise" and "precise_x" are
// other words; comments are not told apart), and it holds no token pasting (`##`).
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
