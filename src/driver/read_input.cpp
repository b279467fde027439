#include "driver/read_input.h"

#include <cstdint>

#include "base/file_io/read_regular_file.h"
#include "base/limits.h"

namespace shaderport::driver {
namespace {

InputText Reject(std::string rule_id, std::string message) {
  return {std::nullopt, std::move(rule_id), std::move(message)};
}

// Share of control bytes (other than whitespace) in the first few KiB: text has
// almost none, binary data many.
bool LooksBinary(std::string_view text) {
  if (text.find('\0') != std::string_view::npos) return true;
  const std::string_view head = text.substr(0, 4096);
  // Control bytes are those below 0x20 but \t \n \v \f \r (9 to 13): two comparisons
  // without branches or a table, which the compiler turns into vector code (this runs
  // over every file checked).
  size_t control = 0;
  for (const char c : head) {
    const auto byte = static_cast<uint8_t>(c);
    control += static_cast<size_t>((byte < 0x20) & (static_cast<uint8_t>(byte - 9) > 4));
  }
  return control * 10 > head.size();
}

}  // namespace

std::string MebibytesOf(size_t bytes) {
  // Rounded up to a tenth, so that a file past the limit never reads as the limit.
  const size_t tenths = (bytes * 10 + (size_t{1} << 20) - 1) >> 20;
  return std::to_string(tenths / 10) + (tenths % 10 != 0 ? "." + std::to_string(tenths % 10) : "");
}

size_t InputLimitFor(const std::filesystem::path& path) {
  return path.extension() == ".jsonl" ? limits::kMaxJsonLinesBytes : limits::kMaxFileBytes;
}

InputText ClassifyInputText(std::string text, size_t limit) {
  if (text.size() > limit) {
    return Reject("input/too-large", "file is " + MebibytesOf(text.size()) +
                                         " MiB, larger than the " + MebibytesOf(limit) +
                                         " MiB limit");
  }
  const bool byte_order_mark = text.starts_with("\xEF\xBB\xBF");
  if (byte_order_mark) text.erase(0, 3);
  if (text.empty()) return Reject("input/empty", "file is empty");
  if (LooksBinary(text)) {
    return Reject("input/binary", "file looks like binary data, not shader source");
  }
  // A lone CR ends a line for browsers and our lexer, but glslang counts only LF
  // and would put everything after it on line 1. LF in its place keeps every
  // offset, so positions agree everywhere (fix and port then write LF there).
  // Most files have no CR at all: find() skips to each one instead of testing every byte.
  for (size_t i = text.find('\r'); i != std::string::npos; i = text.find('\r', i + 1)) {
    if (i + 1 == text.size() || text[i + 1] != '\n') text[i] = '\n';
  }
  return {std::move(text), "", "", byte_order_mark};
}

InputText ReadInputFile(const std::filesystem::path& path) {
  const size_t limit = InputLimitFor(path);
  file_io::ReadResult read = file_io::ReadRegularFile(path, limit);
  switch (read.failure) {
    case file_io::ReadFailure::kNone:
      return ClassifyInputText(std::move(*read.bytes), limit);
    case file_io::ReadFailure::kTooLarge:
      return Reject("input/too-large", "file is " + MebibytesOf(read.size) +
                                           " MiB, larger than the " + MebibytesOf(limit) +
                                           " MiB limit");
    default:
      return Reject("input/unreadable", std::move(read.message));
  }
}

InputText ReadInputStream(std::istream& in) {
  std::string text;
  char buffer[65536];
  while (text.size() <= limits::kMaxFileBytes && in.read(buffer, sizeof buffer).gcount() > 0) {
    text.append(buffer, static_cast<size_t>(in.gcount()));
  }
  if (in.bad()) return Reject("input/unreadable", "cannot read standard input");
  if (text.size() > limits::kMaxFileBytes) {
    return Reject("input/too-large", "standard input is larger than the " +
                                         MebibytesOf(limits::kMaxFileBytes) + " MiB limit");
  }
  return ClassifyInputText(std::move(text));
}

}  // namespace shaderport::driver
