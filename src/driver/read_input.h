// Reads one input file within the size limit and rejects what is not shader text.
#pragma once

#include <filesystem>
#include <istream>
#include <optional>
#include <string>

#include "base/limits.h"
#include "diag/diagnostic.h"

namespace shaderport::driver {

struct InputText {
  std::optional<std::string> text;  // empty optional when the file was rejected
  std::string rule_id;              // why it was rejected ("input/too-large", ...)
  std::string message;
  // The text began with a UTF-8 byte order mark, which `text` no longer holds:
  // clang and the browser's TextDecoder (fetch().text()) skip it, glslang alone
  // rejects it; `fix` writes it back.
  bool byte_order_mark = false;
};

// The size is checked before anything is read, so a huge file costs nothing. Only
// regular files are read: a FIFO, device or directory is rejected without blocking.
InputText ReadInputFile(const std::filesystem::path& path);

// Reads a stream (standard input) within the same limit: reading stops one buffer
// (64 KiB) past the limit, so an endless stream costs nothing.
InputText ReadInputStream(std::istream& in);

// Classifies text already in memory (stdin, tests): "" when it looks like shader source.
// Accepted text has a leading UTF-8 byte order mark removed and each lone CR turned
// into LF (same offsets; glslang counts only LF).
// `limit`: the input limit of the file (InputLimitFor).
InputText ClassifyInputText(std::string text, size_t limit = limits::kMaxFileBytes);

// The most a file may hold: kMaxJsonLinesBytes for a .jsonl file (its limit per
// project applies to each line), kMaxFileBytes for any other.
size_t InputLimitFor(const std::filesystem::path& path);

// "8.1" for 8.1 MiB: rounded up to a tenth (a file past a limit never reads as it).
std::string MebibytesOf(size_t bytes);

}  // namespace shaderport::driver
