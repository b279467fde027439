// glslang's preprocessor copies the spelling of every punctuator it hands to the
// parser with snprintf(name, size, "%s", spelling): libc's format machinery for a
// string copy, about a seventeenth of `check`'s instructions. The link wraps snprintf
// (-Wl,--wrap, CMakeLists.txt) with a copy for exactly the format "%s" that gives the
// same bytes and result; every other format goes to vsnprintf.
#pragma once

#include <cstdint>

namespace shaderport::validate {

// Whether this build wraps snprintf at all (see CMakeLists.txt).
bool SnprintfFastPathLinked();

// Calls on this thread that took the "%s" copy so far (for tests).
uint64_t SnprintfFastPathCopiesOnThisThread();

}  // namespace shaderport::validate
