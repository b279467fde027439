#include "glsl/syntax/keywords.h"

#include <algorithm>
#include <array>

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

constexpr auto Sorted() {
  auto rows = kUnsorted;
  std::sort(rows.begin(), rows.end(),
            [](const KeywordRow& a, const KeywordRow& b) { return a.word < b.word; });
  return rows;
}

constexpr auto kRows = Sorted();

}  // namespace

WordInfo ClassifyWord(std::string_view word, int version) {
  auto it =
      std::lower_bound(kRows.begin(), kRows.end(), word,
                       [](const KeywordRow& r, std::string_view key) { return r.word < key; });
  if (it == kRows.end() || it->word != word) return {};
  WordStatus status = version >= 300 ? it->es300 : it->es100;
  return {status, status == WordStatus::kKeyword ? it->role : WordRole::kNone};
}

}  // namespace shaderport::glsl
