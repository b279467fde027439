#include <array>
#include <cstdint>
#include <string_view>
#include <utility>

#include "glsl/lex/lexer.h"
#include "glsl/lex/punctuators_internal.h"

namespace shaderport::glsl {
namespace {

// Longest spellings first, so that a prefix scan finds the longest match.
constexpr std::array<std::pair<std::string_view, Punct>, 48> kPunctuators = {{
    {"<<=", Punct::kShiftLeftEqual},
    {">>=", Punct::kShiftRightEqual},
    {"++", Punct::kPlusPlus},
    {"--", Punct::kMinusMinus},
    {"<=", Punct::kLessEqual},
    {">=", Punct::kGreaterEqual},
    {"==", Punct::kEqualEqual},
    {"!=", Punct::kNotEqual},
    {"&&", Punct::kAndAnd},
    {"||", Punct::kOrOr},
    {"^^", Punct::kXorXor},
    {"<<", Punct::kShiftLeft},
    {">>", Punct::kShiftRight},
    {"+=", Punct::kPlusEqual},
    {"-=", Punct::kMinusEqual},
    {"*=", Punct::kStarEqual},
    {"/=", Punct::kSlashEqual},
    {"%=", Punct::kPercentEqual},
    {"&=", Punct::kAmpEqual},
    {"|=", Punct::kPipeEqual},
    {"^=", Punct::kCaretEqual},
    {"##", Punct::kHashHash},
    {"(", Punct::kLeftParen},
    {")", Punct::kRightParen},
    {"[", Punct::kLeftBracket},
    {"]", Punct::kRightBracket},
    {"{", Punct::kLeftBrace},
    {"}", Punct::kRightBrace},
    {".", Punct::kDot},
    {",", Punct::kComma},
    {":", Punct::kColon},
    {";", Punct::kSemicolon},
    {"?", Punct::kQuestion},
    {"+", Punct::kPlus},
    {"-", Punct::kMinus},
    {"*", Punct::kStar},
    {"/", Punct::kSlash},
    {"%", Punct::kPercent},
    {"<", Punct::kLess},
    {">", Punct::kGreater},
    {"!", Punct::kBang},
    {"~", Punct::kTilde},
    {"&", Punct::kAmp},
    {"|", Punct::kPipe},
    {"^", Punct::kCaret},
    {"=", Punct::kEqual},
    {"#", Punct::kHashInLine},
    {"", Punct::kNone},
}};

// For each first character, the entries that start with it, longest first: the
// lexer asks for every operator, and a scan of all 48 spellings was 8 % of `check`.
struct Candidates {
  std::array<uint8_t, 6> index{};
  uint8_t count = 0;
};

constexpr std::array<Candidates, 128> kByFirstChar = [] {
  std::array<Candidates, 128> table{};
  for (size_t i = 0; i < kPunctuators.size() && !kPunctuators[i].first.empty(); ++i) {
    Candidates& entry = table[static_cast<unsigned char>(kPunctuators[i].first[0])];
    entry.index[entry.count++] = static_cast<uint8_t>(i);
  }
  return table;
}();

}  // namespace

std::string_view PunctSpelling(Punct punct) {
  for (const auto& [spelling, p] : kPunctuators) {
    if (p == punct) return spelling;
  }
  return {};
}

Punct MatchPunctuator(char c0, char c1, char c2, int* length) {
  *length = 0;
  const auto first = static_cast<unsigned char>(c0);
  if (first >= kByFirstChar.size()) return Punct::kNone;
  const Candidates& candidates = kByFirstChar[first];
  for (uint8_t k = 0; k < candidates.count; ++k) {
    const auto& [spelling, punct] = kPunctuators[candidates.index[k]];
    // The first character matches by construction; compare the rest inline (a memcmp
    // call per candidate cost more than the comparison).
    const size_t size = spelling.size();
    if ((size < 2 || spelling[1] == c1) && (size < 3 || spelling[2] == c2)) {
      *length = static_cast<int>(spelling.size());
      return punct;
    }
  }
  return Punct::kNone;
}

Punct PunctFromSpelling(std::string_view text) {
  if (text.empty() || text.size() > 3) return Punct::kNone;
  for (const auto& [spelling, p] : kPunctuators) {
    if (!spelling.empty() && spelling == text) return p;
  }
  return Punct::kNone;
}

}  // namespace shaderport::glsl
