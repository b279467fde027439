// Writing what `fix` and `port` produce: whole files atomically, and unified diffs.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace shaderport::driver {

// Writes `text` to `path` through a temporary file in the same directory
// (fsync, then rename), keeping the mode of the file it replaces. On any
// failure the old file is untouched, the temporary is removed, and the reason
// is returned; "" on success.
std::string WriteFileAtomically(const std::filesystem::path& path, std::string_view text);

// Where `--out-dir DIR` puts an input whose layout below its argument is
// `relative` (InputFile::relative): DIR/relative with `extension`. An absolute
// path keeps only its file name and leading ".." are dropped, so nothing lands
// outside DIR.
std::filesystem::path OutDirPath(const std::filesystem::path& out_dir,
                                 const std::filesystem::path& relative, std::string_view extension);

// "" when the targets are distinct and none of them is one of the inputs (which
// writing would replace); else a message naming the clash. Empty targets (nothing
// to write) are ignored; `targets[i]` is written from `inputs[i]`.
std::string OutputClash(const std::vector<std::filesystem::path>& inputs,
                        const std::vector<std::filesystem::path>& targets);

// A unified diff (3 lines of context) from `before` to `after`, with
// `a/NAME` and `b/NAME` headers; "" when they are equal.
std::string UnifiedDiff(std::string_view before, std::string_view after, const std::string& name);

}  // namespace shaderport::driver
