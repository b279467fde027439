// Whether an output path can be written at all, asked before the work that
// produces the output (`render -o` draws for seconds before it writes).
#pragma once

#include <filesystem>
#include <string>

namespace shaderport::file_io {

// "" when `target` looks writable: its directory exists and may be written, and
// it is not itself a directory. Else "cannot write TARGET: REASON". A write can
// still fail later (a full disk); this only catches the mistakes in the path.
std::string UnwritablePath(const std::filesystem::path& target);

}  // namespace shaderport::file_io
