// Helper text made safe among a user's macros: every name of its own prefixed, and
// swizzles spelled with letters no macro takes.
#include <algorithm>
#include <cctype>
#include <set>
#include <string>

#include "glsl/lex/lex_chars.h"
#include "glsl/webgl_semantics/cpu_math_library.h"

namespace shaderport::glsl {
namespace {

bool IsNumericType(std::string_view word) {
  return word == "float" || word == "int" || word == "uint" || word.starts_with("vec") ||
         word.starts_with("ivec") || word.starts_with("uvec");
}

}  // namespace

std::string MacroProofHelperText(std::string_view text, std::string_view swizzle_letters) {
  // Keywords and built-ins the helpers use; everything else gets the prefix.
  constexpr std::string_view kKept =
      " float vec2 vec3 vec4 int ivec2 ivec3 ivec4 uint uvec2 uvec3 uvec4 bool bvec2 bvec3 bvec4 "
      "return if else "
      "uniform highp true false abs sign roundEven floor sqrt min max clamp mix equal notEqual "
      "lessThan greaterThan "
      "intBitsToFloat floatBitsToInt uintBitsToFloat isinf mod dFdx dFdy gl_FragCoord ";
  auto kept = [&](std::string_view word) {
    return kKept.find(" " + std::string(word) + " ") != std::string_view::npos;
  };
  constexpr std::string_view kPrefix = "shaderport_";
  std::string out;
  for (size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (std::isdigit(c)) {  // a number with its suffix and exponent
      while (i < text.size() &&
             (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '.' ||
              ((text[i] == '-' || text[i] == '+') && (text[i - 1] == 'e' || text[i - 1] == 'E')))) {
        out.push_back(text[i++]);
      }
      continue;
    }
    if (!std::isalpha(c) && c != '_') {
      out.push_back(text[i++]);
      continue;
    }
    size_t end = i;
    while (end < text.size() &&
           (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '_')) {
      ++end;
    }
    const std::string_view word = text.substr(i, end - i);
    const size_t component = std::string_view("xyzw").find(word.front());
    if (!out.empty() && out.back() == '.' && word.size() == 1 &&
        component != std::string_view::npos) {
      if (swizzle_letters.size() == 4) {
        out.push_back(swizzle_letters[component]);
      } else {  // `.z` would meet a user's `#define z ...`
        out.back() = '[';
        out.push_back(static_cast<char>('0' + component));
        out.push_back(']');
      }
    } else if (word.starts_with(kPrefix) || kept(word)) {
      // A declaration's type gets `highp`: a WebGL2 fragment shader's default int
      // precision is mediump, which Mesa computes in 16 bits.
      const bool declares =
          IsNumericType(word) && end < text.size() && text[end] == ' ' && end + 1 < text.size() &&
          (std::isalpha(static_cast<unsigned char>(text[end + 1])) || text[end + 1] == '_') &&
          !out.ends_with("highp ");
      if (declares) out.append("highp ");
      out.append(word);
    } else {
      out.append(kPrefix).append(word);
    }
    i = end;
  }
  return out;
}

std::string_view SwizzleLettersFreeOfMacros(std::span<const std::string_view> texts) {
  // Blanks and line continuations, as the preprocessor reads a directive line.
  const auto skip_blanks = [](std::string_view text, size_t i) {
    for (i = SkipContinuations(text, i); i < text.size() && IsHorizontalSpace(text[i]);) {
      i = SkipContinuations(text, i + 1);
    }
    return i;
  };
  std::set<char> defined;
  for (const std::string_view text : texts) {
    for (size_t at = text.find('#'); at != std::string_view::npos; at = text.find('#', at + 1)) {
      size_t i = skip_blanks(text, at + 1);
      if (text.compare(i, 6, "define") != 0) continue;
      i = skip_blanks(text, i + 6);
      if (i >= text.size() || !IsIdentifierStart(text[i]) || text[i] == '_') continue;
      const size_t next = SkipContinuations(text, i + 1);
      if (next >= text.size() || !IsIdentifierChar(text[next])) defined.insert(text[i]);
    }
  }
  for (const std::string_view letters : {"xyzw", "rgba", "stpq"}) {
    if (std::none_of(letters.begin(), letters.end(),
                     [&](char letter) { return defined.contains(letter); })) {
      return letters;
    }
  }
  return {};
}

}  // namespace shaderport::glsl
