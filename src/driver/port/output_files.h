// Writing what `fix` and `port` produce: whole files atomically, and unified diffs.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace shaderport::driver {

// Writes `text` to `path` through a temporary file in the same directory
// (fsync, then rename), keeping the mode of the file it replaces. On any
// failure the old file is untouched, the temporary is removed, and the reason
// is returned; "" on success.
std::string WriteFileAtomically(const std::filesystem::path& path, std::string_view text);

// A unified diff (3 lines of context) from `before` to `after`, with
// `a/NAME` and `b/NAME` headers; "" when they are equal.
std::string UnifiedDiff(std::string_view before, std::string_view after, const std::string& name);

}  // namespace shaderport::driver
