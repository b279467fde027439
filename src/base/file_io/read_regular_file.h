// Reading a file shaderport did not write for this run (an input, a baseline, a
// report to merge, a cache entry, a configuration, a dialect, a channel image):
// only a regular file, opened without blocking, never more than a set size.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

namespace shaderport::file_io {

enum class ReadFailure {
  kNone,
  kCannotOpen,   // open() failed (missing, permission): `message` has the reason
  kNotRegular,   // a directory, FIFO, socket or device: nothing was read
  kTooLarge,     // larger than the cap: nothing was read
  kCannotRead,   // read() failed
  kChangedSize,  // the file shrank or grew while it was read
};

struct ReadResult {
  std::optional<std::string> bytes;  // the whole file; nullopt on any failure
  ReadFailure failure = ReadFailure::kNone;
  std::string message;  // why, without the path: "not a regular file: a FIFO"
  uintmax_t size = 0;   // the file's size when it was too large
};

// The file's bytes. The file is opened with O_NONBLOCK, so a FIFO without a writer
// cannot make the open wait; fstat on the open descriptor then rejects anything but
// a regular file, and a size above `max_bytes` before a byte is read, so neither
// /dev/zero nor a huge file costs memory.
ReadResult ReadRegularFile(const std::filesystem::path& path, size_t max_bytes);

// At most the first `max_bytes` of the file, read as ReadRegularFile reads: ""
// when it is not a regular file or cannot be read.
std::string ReadRegularFileHead(const std::filesystem::path& path, size_t max_bytes);

// "N MiB" (or "N KiB", "N bytes" below that) for messages about a size limit.
std::string SizeLimitText(size_t bytes);

}  // namespace shaderport::file_io
