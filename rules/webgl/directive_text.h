// Line and word scanning for the text glslang compiles (glslang_divergence.cpp): the
// directives and words its edits look for, read by hand. std::regex did this before
// and cost a quarter of check's CPU time (most of it in locale lookups).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace shaderport::rules::directive_text {

// A letter, digit or '_': the characters of a word (regex `\w`).
bool IsWordChar(char c);

// Whether `word` is spelled at `at` (the first character is compared first: this is
// called for every character of a shader).
inline bool StartsAt(std::string_view text, size_t at, std::string_view word) {
  return at < text.size() && text[at] == word.front() && text.substr(at, word.size()) == word;
}

// `text` split at '\n' (the line breaks are not part of the lines); calls
// `line(view, offset)` for each line, also the last one after a final '\n'.
template <typename Callback>
void ForEachLine(std::string_view text, Callback&& line) {
  size_t begin = 0;
  while (true) {
    const size_t end = text.find('\n', begin);
    if (end == std::string_view::npos) {
      line(text.substr(begin), begin);
      return;
    }
    line(text.substr(begin, end - begin), begin);
    begin = end + 1;
  }
}

// Calls `word(view, offset)` for each identifier of `text`: a maximal run of word
// characters that starts with a letter or '_' (a run starting with a digit is a number).
template <typename Callback>
void ForEachIdentifier(std::string_view text, Callback&& word) {
  for (size_t i = 0; i < text.size();) {
    if (!IsWordChar(text[i])) {
      ++i;
      continue;
    }
    size_t end = i;
    while (end < text.size() && IsWordChar(text[end])) ++end;
    const char first = text[i];
    if (first < '0' || first > '9') word(text.substr(i, end - i), i);
    i = end;
  }
}

// Whether `word` stands in `text` as a whole word.
bool ContainsWord(std::string_view text, std::string_view word);

// A `#define` line: blanks, '#', blanks, `define`, blanks, NAME.
struct DefineLine {
  std::string_view name;
  size_t name_begin = 0;
  size_t name_end = 0;  // just after NAME: the parameter list's '(' when function-like
  bool function_like = false;
};
std::optional<DefineLine> ParseDefine(std::string_view line);

// The directive's keyword (`if`, `define`, ...) when the line is one: blanks, '#',
// blanks, then a run of lower-case letters; empty otherwise.
std::string_view DirectiveKeyword(std::string_view line);

// The directive `#keyword`, the keyword standing as a word (`#if` is not `#ifdef`).
bool IsDirective(std::string_view line, std::string_view keyword);
// `#if` or `#elif` (not `#ifdef`, `#ifndef`).
bool IsIfOrElif(std::string_view line);

// `#define NAME VALUE`, VALUE one unsigned literal (`26u`, `0xFFu`), optionally in
// parentheses and followed by a `//` comment: NAME, and VALUE without its suffix.
struct UnsignedDefine {
  std::string name;
  std::string value;
};
std::optional<UnsignedDefine> ParseUnsignedDefine(std::string_view line);

// `text` with the `u`/`U` suffix of every unsigned integer literal removed (`2u` is
// `2`); a literal is a number standing as a word of its own.
std::string WithoutUnsignedSuffixes(std::string_view text);

// `NAME()` alone: an identifier, blanks, '(', blanks, ')'.
bool IsEmptyCall(std::string_view text);
// `(,`, `,,` or `,)` with blanks allowed between: an empty macro argument.
bool HasEmptyArgument(std::string_view text);

}  // namespace shaderport::rules::directive_text
