#include "report/source_position.h"

#include <algorithm>

namespace shaderport {
namespace {

bool IsContinuationByte(unsigned char byte) { return (byte & 0xC0) == 0x80; }

// Length of the UTF-8 sequence that `lead` starts (1 for an invalid lead byte).
uint32_t SequenceLength(unsigned char lead) {
  if (lead >= 0xF0 && lead <= 0xF4) return 4;
  if (lead >= 0xE0) return lead <= 0xEF ? 3 : 1;
  if (lead >= 0xC2) return 2;
  return 1;
}

}  // namespace

uint32_t Utf16Column(std::string_view line, uint32_t byte_column) {
  const size_t limit = std::min<size_t>(byte_column > 0 ? byte_column - 1 : 0, line.size());
  uint32_t units = 0;
  size_t i = 0;
  while (i < limit) {
    const auto lead = static_cast<unsigned char>(line[i]);
    uint32_t length = SequenceLength(lead);
    // A sequence cut short by the end of the line or by a non-continuation byte is
    // invalid: its lead byte then counts alone.
    bool valid = i + length <= line.size();
    for (uint32_t k = 1; valid && k < length; ++k) {
      valid = IsContinuationByte(static_cast<unsigned char>(line[i + k]));
    }
    if (!valid) length = 1;
    units += (valid && length == 4) ? 2 : 1;
    i += length;
  }
  // A column that points inside a multi-byte character rounds up to the next one.
  return units + 1;
}

uint32_t CountCodePoints(std::string_view bytes) {
  uint32_t count = 0;
  for (char c : bytes) {
    if (!IsContinuationByte(static_cast<unsigned char>(c))) ++count;
  }
  return count;
}

std::optional<ResolvedRange> Resolve(const SourceManager* sources, const SourceRange& range) {
  if (sources == nullptr || !range.Valid() || range.file >= sources->Size()) return std::nullopt;
  const SourceFile& file = sources->Get(range.file);
  const auto size = static_cast<uint32_t>(file.Text().size());
  ResolvedRange resolved;
  resolved.file = &file;
  resolved.begin_offset = std::min(range.begin, size);
  resolved.end_offset = std::clamp(range.end, resolved.begin_offset, size);
  resolved.start = file.LocationOf(resolved.begin_offset);
  resolved.end = file.LocationOf(resolved.end_offset);
  resolved.start_utf16 = {resolved.start.line,
                          Utf16Column(file.LineText(resolved.start.line), resolved.start.column)};
  resolved.end_utf16 = {resolved.end.line,
                        Utf16Column(file.LineText(resolved.end.line), resolved.end.column)};
  return resolved;
}

std::optional<ResolvedRange> ResolveInContainer(const ResolvedRange& where) {
  const Embedding* embedding = where.file != nullptr ? where.file->Embedded() : nullptr;
  if (embedding == nullptr || embedding->container == nullptr) return std::nullopt;
  const SourceFile& container = *embedding->container;
  ResolvedRange resolved;
  resolved.file = &container;
  resolved.begin_offset = embedding->ContainerOffset(where.begin_offset);
  resolved.end_offset =
      std::max(resolved.begin_offset, embedding->ContainerOffset(where.end_offset));
  resolved.start = container.LocationOf(resolved.begin_offset);
  resolved.end = container.LocationOf(resolved.end_offset);
  resolved.start_utf16 = {resolved.start.line, Utf16Column(container.LineText(resolved.start.line),
                                                           resolved.start.column)};
  resolved.end_utf16 = {resolved.end.line,
                        Utf16Column(container.LineText(resolved.end.line), resolved.end.column)};
  return resolved;
}

bool IsAbsolutePath(std::string_view path) {
  if (!path.empty() && (path[0] == '/' || path[0] == '\\')) return true;
  // "C:/..." or "C:\..."
  return path.size() >= 3 && path[1] == ':' && (path[2] == '/' || path[2] == '\\');
}

std::string DisplayPath(std::string_view name, std::string_view base_directory) {
  std::string path(name);
  std::replace(path.begin(), path.end(), '\\', '/');
  std::string base(base_directory);
  std::replace(base.begin(), base.end(), '\\', '/');
  while (base.size() > 1 && base.back() == '/') base.pop_back();
  if (!base.empty() && IsAbsolutePath(path) && path.size() > base.size() + 1 &&
      path.compare(0, base.size(), base) == 0 && (base == "/" || path[base.size()] == '/')) {
    path.erase(0, base == "/" ? 1 : base.size() + 1);
  }
  while (path.size() > 2 && path.compare(0, 2, "./") == 0) path.erase(0, 2);
  return path;
}

std::string EncodeUriPath(std::string_view path) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out;
  out.reserve(path.size());
  for (char c : path) {
    const auto byte = static_cast<unsigned char>(c);
    const bool unreserved = (byte >= 'A' && byte <= 'Z') || (byte >= 'a' && byte <= 'z') ||
                            (byte >= '0' && byte <= '9') || byte == '-' || byte == '.' ||
                            byte == '_' || byte == '~' || byte == '/';
    if (unreserved) {
      out += c;
    } else {
      out += '%';
      out += kHex[byte >> 4];
      out += kHex[byte & 0xF];
    }
  }
  return out;
}

}  // namespace shaderport
