// The Language Server Protocol's base protocol on a byte stream: each message is
// headers ("Content-Length: N", CRLF each), a blank line, then N bytes of JSON.
#pragma once

#include <cstddef>
#include <cstdio>
#include <optional>
#include <string>

namespace shaderport::cli {

// Beyond this a message is refused (and the stream skipped past it): the largest
// input shaderport reads is 8 MiB, and JSON escaping can double it.
inline constexpr size_t kMaxLspMessageBytes = 64u << 20;

struct FramedMessage {
  std::string body;   // the JSON text
  std::string error;  // a header the server cannot use ("" when the body is whole)
};

// The next message of `in`; nothing at the end of the stream (or a stream cut
// inside a message).
std::optional<FramedMessage> ReadFramedMessage(std::FILE* in);

// Writes `json` with its Content-Length header and flushes.
void WriteFramedMessage(std::FILE* out, const std::string& json);

}  // namespace shaderport::cli
