// Glob patterns of .shaderport.toml, matched against '/'-separated paths
// relative to the config file's directory:
//   *    any run of characters within one path segment
//   **   any run of characters across segments ("**/" also matches no directory)
//   ?    one character other than '/'
// A leading '/' anchors at the config directory, which every pattern is anyway.
#pragma once

#include <string>
#include <string_view>

namespace shaderport::driver {

// "" when `pattern` is usable, else why not.
std::string GlobError(std::string_view pattern);

// Linear in pattern size times path size: no backtracking blow-up on hostile patterns.
bool GlobMatches(std::string_view pattern, std::string_view path);

}  // namespace shaderport::driver
