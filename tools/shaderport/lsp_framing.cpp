#include "lsp_framing.h"

#include <cctype>
#include <charconv>

namespace shaderport::cli {
namespace {

// One header line without its CRLF (a bare LF is taken too); nothing at the end.
std::optional<std::string> ReadHeaderLine(std::FILE* in) {
  std::string line;
  for (int c = std::fgetc(in); c != EOF; c = std::fgetc(in)) {
    if (c == '\n') {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      return line;
    }
    if (line.size() < 4096) line += static_cast<char>(c);  // a header is short
  }
  return std::nullopt;
}

bool StartsWithCaseless(const std::string& text, const std::string& prefix) {
  if (text.size() < prefix.size()) return false;
  for (size_t i = 0; i < prefix.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(text[i])) != prefix[i]) return false;
  }
  return true;
}

}  // namespace

std::optional<FramedMessage> ReadFramedMessage(std::FILE* in) {
  std::optional<size_t> length;
  FramedMessage message;
  bool any_header = false;
  while (true) {
    std::optional<std::string> line = ReadHeaderLine(in);
    if (!line) return std::nullopt;
    if (line->empty()) {
      if (any_header) break;
      continue;  // blank lines between messages
    }
    any_header = true;
    if (StartsWithCaseless(*line, "content-length:")) {
      size_t value = 0;
      const char* begin = line->data() + 15;
      while (*begin == ' ') ++begin;
      const char* end = line->data() + line->size();
      const auto [at, error] = std::from_chars(begin, end, value);
      if (error == std::errc() && at == end) length = value;
    }
  }
  if (!length) {
    message.error = "no Content-Length header";
    return message;
  }
  const size_t wanted = *length;
  const size_t kept = wanted <= kMaxLspMessageBytes ? wanted : 0;
  message.body.resize(kept);
  if (kept > 0 && std::fread(message.body.data(), 1, kept, in) != kept) return std::nullopt;
  // Too large: read past it in pieces, keep nothing.
  for (size_t skipped = kept; skipped < wanted;) {
    char buffer[65536];
    const size_t piece = std::min(sizeof buffer, wanted - skipped);
    if (std::fread(buffer, 1, piece, in) != piece) return std::nullopt;
    skipped += piece;
  }
  if (kept != wanted) {
    message.error = "the message is " + std::to_string(wanted) + " bytes, more than the " +
                    std::to_string(kMaxLspMessageBytes) + " a message may have";
  }
  return message;
}

void WriteFramedMessage(std::FILE* out, const std::string& json) {
  std::fprintf(out, "Content-Length: %zu\r\n\r\n", json.size());
  std::fwrite(json.data(), 1, json.size(), out);
  std::fflush(out);
}

}  // namespace shaderport::cli
