// Turns byte ranges into what each output format prints: line/column pairs in
// bytes (text, JSON) or UTF-16 code units (SARIF, GitHub), and display paths.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "source/source_file.h"
#include "source/source_manager.h"

namespace shaderport {

// A range resolved against its file. Columns are 1-based; `end` is exclusive.
struct ResolvedRange {
  const SourceFile* file = nullptr;
  uint32_t begin_offset = 0;
  uint32_t end_offset = 0;
  LineColumn start;  // byte columns, as clang prints them
  LineColumn end;
  LineColumn start_utf16;  // UTF-16 code-unit columns, as SARIF counts them
  LineColumn end_utf16;
};

// nullopt for an invalid range or a file id the manager does not know. Offsets
// past the end of the file are clamped and a reversed range is made empty, so a
// buggy producer cannot make a printer read out of bounds.
std::optional<ResolvedRange> Resolve(const SourceManager* sources, const SourceRange& range);

// For a range in a file embedded in another (a pass of a JSON project): the same
// range in the container's own lines and columns; nullopt when not embedded.
std::optional<ResolvedRange> ResolveInContainer(const ResolvedRange& where);

// The 1-based UTF-16 column of byte column `byte_column` (1-based) in `line`.
// Invalid UTF-8 bytes count as one unit each, as a decoder that replaces them would.
uint32_t Utf16Column(std::string_view line, uint32_t byte_column);

// How many characters (code points) `bytes` holds: UTF-8 continuation bytes are not counted.
uint32_t CountCodePoints(std::string_view bytes);

// `name` with '\' turned into '/', a leading "./" dropped and, when it lies under
// the absolute `base_directory`, made relative to it.
std::string DisplayPath(std::string_view name, std::string_view base_directory);

bool IsAbsolutePath(std::string_view path);

// Percent-encodes the bytes a URI may not hold as they are (RFC 3986); '/' is kept.
std::string EncodeUriPath(std::string_view path);

}  // namespace shaderport
