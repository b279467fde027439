// Output paths of `port --out-dir` (OutDirPath, OutputClash), outputs that would
// replace an input, and unified diffs; files are written by WriteFileAtomically
// (atomic_write.h).
#pragma once

#include <filesystem>
#include <span>
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

// "" when `output` is none of `inputs`; else "OPTION OUTPUT is the input INPUT: writing
// would replace it; nothing was written". Compared by file identity (device and
// inode), so another spelling, a symlink or a hard link of an input is caught too.
std::string OutputReplacesInput(std::string_view option, const std::filesystem::path& output,
                                std::span<const std::filesystem::path> inputs);

// Writes `text` to `target` atomically, making its directory first (an --out-dir
// layout); "" on success, else why not.
std::string WriteOutput(const std::filesystem::path& target, std::string_view text);

// A unified diff (3 lines of context) from `before` to `after`, with
// `a/NAME` and `b/NAME` headers; "" when they are equal.
std::string UnifiedDiff(std::string_view before, std::string_view after, const std::string& name);

}  // namespace shaderport::driver
