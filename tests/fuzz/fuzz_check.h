// The one assertion every fuzz target uses: a broken property aborts, so
// libFuzzer records the input as a crash and saves it as an artifact.
#pragma once

#include <cstdio>
#include <cstdlib>

namespace shaderport::fuzz {

// Aborts with `what` unless `ok`.
inline void Check(bool ok, const char* target, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "%s: %s\n", target, what);
  std::abort();
}

}  // namespace shaderport::fuzz
