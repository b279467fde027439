#include "driver/lsp/lsp_text.h"

#include <algorithm>

namespace shaderport::driver::lsp {
namespace {

// Bytes in the UTF-8 sequence led by `lead` (1 for a stray continuation byte, so
// that broken text still advances).
uint32_t SequenceLength(unsigned char lead) {
  if (lead >= 0xF0) return 4;
  if (lead >= 0xE0) return 3;
  if (lead >= 0xC0) return 2;
  return 1;
}

uint32_t LineStart(std::string_view text, uint32_t line) {
  uint32_t offset = 0;
  for (uint32_t at = 0; at < line; ++at) {
    const size_t newline = text.find('\n', offset);
    if (newline == std::string_view::npos) return static_cast<uint32_t>(text.size());
    offset = static_cast<uint32_t>(newline + 1);
  }
  return offset;
}

}  // namespace

Position PositionOf(std::string_view text, uint32_t offset) {
  offset = std::min<uint32_t>(offset, static_cast<uint32_t>(text.size()));
  Position position;
  uint32_t line_start = 0;
  for (size_t newline = text.find('\n'); newline != std::string_view::npos && newline < offset;
       newline = text.find('\n', newline + 1)) {
    ++position.line;
    line_start = static_cast<uint32_t>(newline + 1);
  }
  for (uint32_t at = line_start; at < offset;) {
    const uint32_t length = SequenceLength(static_cast<unsigned char>(text[at]));
    position.character += length == 4 ? 2 : 1;  // beyond the BMP: a surrogate pair
    at += length;
  }
  return position;
}

uint32_t OffsetOf(std::string_view text, Position position) {
  uint32_t at = LineStart(text, position.line);
  uint32_t units = 0;
  while (at < text.size() && text[at] != '\n' && text[at] != '\r' && units < position.character) {
    const uint32_t length = SequenceLength(static_cast<unsigned char>(text[at]));
    units += length == 4 ? 2 : 1;
    at = std::min<uint32_t>(at + length, static_cast<uint32_t>(text.size()));
  }
  return at;
}

nlohmann::json ToJson(Position position) {
  return {{"line", position.line}, {"character", position.character}};
}

std::optional<Position> PositionFromJson(const nlohmann::json& json) {
  if (!json.is_object()) return std::nullopt;
  const auto line = json.find("line");
  const auto character = json.find("character");
  const auto natural = [](const nlohmann::json& value) {
    return value.is_number_unsigned() || (value.is_number_integer() && value.get<int64_t>() >= 0);
  };
  if (line == json.end() || character == json.end() || !natural(*line) || !natural(*character)) {
    return std::nullopt;
  }
  const auto clamp = [](uint64_t value) {
    return static_cast<uint32_t>(std::min<uint64_t>(value, UINT32_MAX));
  };
  return Position{clamp(line->get<uint64_t>()), clamp(character->get<uint64_t>())};
}

bool ApplyChange(std::string& text, const nlohmann::json& change) {
  if (!change.is_object()) return false;
  const auto replacement = change.find("text");
  if (replacement == change.end() || !replacement->is_string()) return false;
  const auto range = change.find("range");
  if (range == change.end()) {
    text = replacement->get<std::string>();
    return true;
  }
  if (!range->is_object() || !range->contains("start") || !range->contains("end")) return false;
  const auto start = PositionFromJson((*range)["start"]);
  const auto end = PositionFromJson((*range)["end"]);
  if (!start || !end) return false;
  const uint32_t begin = OffsetOf(text, *start);
  const uint32_t finish = std::max(begin, OffsetOf(text, *end));
  text.replace(begin, finish - begin, replacement->get<std::string>());
  return true;
}

}  // namespace shaderport::driver::lsp
