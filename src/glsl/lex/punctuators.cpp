#include <array>
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

}  // namespace

std::string_view PunctSpelling(Punct punct) {
  for (const auto& [spelling, p] : kPunctuators) {
    if (p == punct) return spelling;
  }
  return {};
}

Punct MatchPunctuator(char c0, char c1, char c2, int* length) {
  const char chars[3] = {c0, c1, c2};
  for (const auto& [spelling, p] : kPunctuators) {
    if (spelling.empty()) break;
    bool match = true;
    for (size_t i = 0; i < spelling.size(); ++i) match = match && chars[i] == spelling[i];
    if (match) {
      *length = static_cast<int>(spelling.size());
      return p;
    }
  }
  *length = 0;
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
