// Positions as the Language Server Protocol counts them (0-based lines, columns in
// UTF-16 code units, its default encoding) against byte offsets, and the edits a
// client sends to an open document (full text, or a range replaced).
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

namespace shaderport::driver::lsp {

struct Position {
  uint32_t line = 0;       // 0-based
  uint32_t character = 0;  // UTF-16 code units from the line's start
};

// The LSP position of byte `offset` of `text` (clamped to the text).
Position PositionOf(std::string_view text, uint32_t offset);

// The byte offset of `position` in `text`: a line past the end is the end, a
// character past the line's end is the line's end (as the protocol asks).
uint32_t OffsetOf(std::string_view text, Position position);

nlohmann::json ToJson(Position position);
// Nothing when `json` is not {"line": N, "character": N} with N >= 0.
std::optional<Position> PositionFromJson(const nlohmann::json& json);

// Applies one TextDocumentContentChangeEvent: {"text"} replaces everything,
// {"range", "text"} the range. False (text unchanged) for a malformed change.
bool ApplyChange(std::string& text, const nlohmann::json& change);

}  // namespace shaderport::driver::lsp
