// Output paths of `port --out-dir` (OutDirPath, OutputClash) and unified diffs;
// files are written by WriteFileAtomically (atomic_write.h).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "base/file_io/atomic_write.h"  // WriteFileAtomically
#include "driver/input_files.h"

namespace shaderport::driver {

// Where `--out-dir DIR` puts an input whose layout below its argument is
// `relative` (InputFile::relative): DIR/relative with `extension`. An absolute
// path keeps only its file name and leading ".." are dropped, so nothing lands
// outside DIR.
std::filesystem::path OutDirPath(const std::filesystem::path& out_dir,
                                 const std::filesystem::path& relative, std::string_view extension);

// One layout for named files and walked directories, as tsc's rootDir: each
// input's `relative` becomes its path below the deepest directory that holds every
// argument (a named file's directory, a walked directory itself). `port --out-dir
// out shaders/` and `port --out-dir out shaders/a/b.glsl shaders/c.glsl` both write
// shaders/a/b.glsl to out/a/b.frag.
void RelativeToCommonRoot(std::vector<InputFile>& inputs);

// "" when the targets are distinct and none of them is one of the inputs (which
// writing would replace); else a message naming the clash. Empty targets (nothing
// to write) are ignored; `targets[i]` is written from `inputs[i]`.
std::string OutputClash(const std::vector<std::filesystem::path>& inputs,
                        const std::vector<std::filesystem::path>& targets);

// A unified diff (3 lines of context) from `before` to `after`, with
// `a/NAME` and `b/NAME` headers; "" when they are equal.
std::string UnifiedDiff(std::string_view before, std::string_view after, const std::string& name);

}  // namespace shaderport::driver
