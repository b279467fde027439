#include "glsl/syntax/keywords.h"

#include <array>
#include <cstddef>
#include <cstdint>

namespace shaderport::glsl {
namespace {

struct KeywordRow {
  std::string_view word;
  WordStatus es100;
  WordStatus es300;
  WordRole role;
};

constexpr auto kUnsorted = std::to_array<KeywordRow>({
#define KEYWORD(word, es100, es300, role) \
  KeywordRow{#word, WordStatus::es100, WordStatus::es300, WordRole::role},
#include "glsl/syntax/keywords.def"
#undef KEYWORD
});

// An open-addressing hash table over the rows, built at compile time: the parser
// classifies every identifier token, and a binary search over the sorted words
// (8 string comparisons a word) was 1.8 % of `check`.
constexpr size_t kSlots = 512;  // a power of two, about three times the rows
static_assert(kSlots > 2 * kUnsorted.size());
constexpr int16_t kEmptySlot = -1;

constexpr uint32_t Hash(std::string_view word) {
  uint32_t hash = 2166136261u;  // FNV-1a
  for (char c : word) {
    hash ^= static_cast<uint8_t>(c);
    hash *= 16777619u;
  }
  return hash;
}

constexpr auto BuildSlots() {
  std::array<int16_t, kSlots> slots{};
  slots.fill(kEmptySlot);
  for (size_t row = 0; row < kUnsorted.size(); ++row) {
    size_t at = Hash(kUnsorted[row].word) & (kSlots - 1);
    while (slots[at] != kEmptySlot) at = (at + 1) & (kSlots - 1);
    slots[at] = static_cast<int16_t>(row);
  }
  return slots;
}

constexpr auto kSlotRows = BuildSlots();

const KeywordRow* Find(std::string_view word) {
  for (size_t at = Hash(word) & (kSlots - 1); kSlotRows[at] != kEmptySlot;
       at = (at + 1) & (kSlots - 1)) {
    const KeywordRow& row = kUnsorted[static_cast<size_t>(kSlotRows[at])];
    if (row.word == word) return &row;
  }
  return nullptr;
}

}  // namespace

WordInfo ClassifyWord(std::string_view word, int version) {
  const KeywordRow* it = Find(word);
  if (it == nullptr) return {};
  WordStatus status = version >= 300 ? it->es300 : it->es100;
  return {status, status == WordStatus::kKeyword ? it->role : WordRole::kNone};
}

}  // namespace shaderport::glsl
