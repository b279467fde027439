// The temporaries WriteFileAtomically stages new text in: their names and the
// removal of ones a killed process left behind.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace shaderport::file_io {

// ".NAME.shaderport-PID-XXXXXX.tmp" with a fresh random XXXXXX.
std::string TemporaryNameFor(std::string_view target_name);

// Removes the temporaries older than kStaleTemporaryAge in `directory`, open as
// `directory_fd`, once per directory path and process (later calls for it do
// nothing, so writing many files in one directory stays linear).
void RemoveStaleTemporaries(int directory_fd, const std::filesystem::path& directory);

}  // namespace shaderport::file_io
