#include "validate/glslang_rules.h"

#include <array>
#include <utility>

namespace shaderport::validate {
namespace {

bool Contains(std::string_view text, std::string_view part) {
  return text.find(part) != std::string_view::npos;
}

// First match wins, so more specific phrases come before general ones.
constexpr auto kRules = std::to_array<std::pair<std::string_view, std::string_view>>({
    {"undeclared identifier", "glslang/undeclared-identifier"},
    {"can't find function", "glslang/undeclared-identifier"},
    {"no matching overloaded function", "glslang/no-matching-overload"},
    {"wrong operand types", "glslang/wrong-operand-types"},
    {"cannot convert", "glslang/type-mismatch"},
    {"default precision qualifier", "glslang/missing-precision"},
    {"non-constant global initializer", "glslang/non-constant-global-initializer"},
    {"non-constant initializer", "glslang/constant-expression-required"},
    {"Reserved word", "glslang/reserved-word"},
    {"reserved word", "glslang/reserved-word"},
    {"are reserved", "glslang/reserved-word"},             // identifiers starting with "gl_"
    {"reserved for future use", "glslang/reserved-word"},  // "__" in identifiers
    {"syntax error", "glslang/syntax-error"},
    {"End of input in comment", "glslang/unterminated-comment"},
    {"Missing entry point", "glslang/missing-entry-point"},
    {"No function definition (body) found", "glslang/missing-entry-point"},
    {"redefinition", "glslang/redefinition"},
    {"redeclaration", "glslang/redefinition"},
    {"redeclared", "glslang/redefinition"},
    {"already been declared", "glslang/redefinition"},
    {"already has a body", "glslang/redefinition"},
    {"constant expression required", "glslang/constant-expression-required"},
    {"must be constant", "glslang/constant-expression-required"},
    {"must be a constant", "glslang/constant-expression-required"},
    {"constant expression", "glslang/constant-expression-required"},
    {"no longer supported", "glslang/unsupported-in-version"},
    {"not supported", "glslang/unsupported-in-version"},
    {"required extension not requested", "glslang/unsupported-in-version"},
    {"Macro", "glslang/preprocessor"},
    {"#endif", "glslang/preprocessor"},
    {"preprocessor", "glslang/preprocessor"},
});

void CollapseSpaces(std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    const bool space = c == ' ' || c == '\t';
    if (space && (out.empty() || out.back() == ' ')) continue;
    out += space ? ' ' : c;
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  text = std::move(out);
}

// Quoted spans alternate open/close; after an opening quote glslang puts a space
// and then the storage class of a type, which we drop when it is "temp" or "global".
void TidyQuotedTypes(std::string& text) {
  std::string out;
  out.reserve(text.size());
  bool inside = false;
  for (size_t i = 0; i < text.size(); ++i) {
    out += text[i];
    if (text[i] != '\'') continue;
    inside = !inside;
    if (!inside) continue;
    std::string_view rest = std::string_view(text).substr(i + 1);
    size_t skip = 0;
    while (skip < rest.size() && rest[skip] == ' ') ++skip;
    for (std::string_view word : {"temp ", "global "}) {
      if (rest.substr(skip).starts_with(word)) skip += word.size();
    }
    // Keep an empty quoted span ('') intact.
    if (skip < rest.size() && rest[skip] != '\'') i += skip;
  }
  text = std::move(out);
}

}  // namespace

std::string_view ClassifyGlslangMessage(const GlslangMessage& message) {
  // glslang sometimes puts the subject in the quoted token and only a generic
  // reason in the text ('non-constant global initializer (...)' : not supported...).
  const std::string text = message.token + ": " + message.text;
  for (const auto& [phrase, rule] : kRules) {
    if (Contains(text, phrase)) return rule;
  }
  // Directives: glslang quotes them as the token ('#version', '#extension', '#if'...).
  if (message.token.starts_with('#')) return "glslang/preprocessor";
  return message.severity == Severity::kError ? "glslang/error" : "glslang/warning";
}

std::string TidyGlslangText(const GlslangMessage& message) {
  std::string text = message.text;
  CollapseSpaces(text);
  TidyQuotedTypes(text);
  if (message.token.empty()) return text;
  return "'" + message.token + "': " + text;
}

}  // namespace shaderport::validate
