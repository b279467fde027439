// State shared by the parts of the preprocessor (not public API): the macro
// table, the result being built, and the budgets that keep hostile input bounded.
#pragma once

#include <bitset>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "glsl/lex/preprocessor.h"

namespace shaderport::glsl {

enum class BuiltinMacro : uint8_t { kNone, kLine, kFile, kVersion };

struct Macro {
  std::string name;
  bool function_like = false;
  bool predefined = false;  // GL_ES, __LINE__, options.predefined: may not be redefined
  BuiltinMacro builtin = BuiltinMacro::kNone;
  std::vector<std::string_view> params;
  std::vector<PpToken> body;
  std::vector<int> body_param;  // per body token: index into params, or -1
  SourceRange definition;       // the name in its #define; invalid for predefined macros
  int disabled = 0;             // > 0 while its expansion is being rescanned
};

struct StringHash {
  using is_transparent = void;
  size_t operator()(std::string_view s) const { return std::hash<std::string_view>{}(s); }
};

using MacroTable = std::unordered_map<std::string, Macro, StringHash, std::equal_to<>>;

// A token during expansion: a PpToken plus C's "painted blue" mark for a macro
// name met while that macro was being expanded (it never expands again).
struct ExpToken {
  PpToken token;
  bool no_expand = false;
};

struct PpState {
  PreprocessResult& result;
  MacroTable macros;
  size_t expanded_tokens = 0;  // budget: tokens made by macro expansion so far
  bool expansion_exhausted = false;
  bool reported_macro_depth = false;
  // For __LINE__ and __FILE__: #line changes them.
  const SourceFile* file = nullptr;
  int64_t line_delta = 0;  // added to the physical line
  int source_number = 0;

  explicit PpState(PreprocessResult& r) : result(r) {}

  // The first characters of every name ever defined: most identifiers of a shader are
  // no macro, and this answers for them without hashing the name.
  std::bitset<256> macro_initials;
  void NoteMacroName(std::string_view name) {
    if (!name.empty()) macro_initials.set(static_cast<unsigned char>(name[0]));
  }
  bool MayBeMacro(std::string_view name) const {
    return name.empty() || macro_initials.test(static_cast<unsigned char>(name[0]));
  }

  const Macro* Find(std::string_view name) const {
    if (!MayBeMacro(name)) return nullptr;
    auto it = macros.find(name);
    return it == macros.end() ? nullptr : &it->second;
  }
  Macro* FindMutable(std::string_view name) {
    if (!MayBeMacro(name)) return nullptr;
    auto it = macros.find(name);
    return it == macros.end() ? nullptr : &it->second;
  }

  // Adds a diagnostic unless limits::kMaxDiagnosticsPerFile were already reported.
  void Report(Severity severity, std::string_view rule, SourceRange range, std::string message);

  // Keeps `text` alive as long as the result and returns a view of it.
  std::string_view Store(std::string text) {
    result.storage.push_back(std::move(text));
    return result.storage.back();
  }
};

// `text` without its line continuations, stored in `state` (the rare case of ToPpToken).
std::string_view StoreLogicalSpelling(std::string_view text, PpState& state);

// Converts a lexed token of `file` to a PpToken spelled where it is written, into `t`
// (a default PpToken): FlushText builds the output in place, without a copy per token.
// `file_has_backslash` false promises that no token of the file holds a line continuation.
// Inline: it runs for every token of every file.
inline void ConvertToPpToken(PpToken& t, const SourceFile& file, const Token& token, PpState& state,
                             bool file_has_backslash = true) {
  t.kind = token.kind;
  t.punct = token.punct;
  t.text = token.text;
  // The parser wants the logical spelling: drop backslash-newlines inside the token.
  if (file_has_backslash && token.text.find('\\') != std::string_view::npos &&
      token.kind != TokenKind::kInvalid) {
    t.text = StoreLogicalSpelling(token.text, state);
  }
  t.spelling = {file.Id(), token.begin, token.end};
  t.expansion = t.spelling;
  t.leading_space = token.leading_space;
  t.at_line_start = token.at_line_start;
}

inline PpToken ToPpToken(const SourceFile& file, const Token& token, PpState& state,
                         bool file_has_backslash = true) {
  PpToken t;
  ConvertToPpToken(t, file, token, state, file_has_backslash);
  return t;
}

// The smallest range covering `a` and `b` when both are in one file in order, else `a`.
SourceRange Cover(SourceRange a, SourceRange b);

}  // namespace shaderport::glsl
