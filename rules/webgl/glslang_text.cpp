// The text glslang is given where glslang and browsers differ on purpose (TextForGlslang,
// glslang_divergence.h): directives and macros as browsers read them, skipped groups
// emptied, extensions the page does not have hidden. Renames: glslang_text_names.cpp.
#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "glsl/sema/builtins.h"
#include "glsl/syntax/visit.h"
#include "rules/webgl/constant_expression.h"
#include "rules/webgl/directive_text.h"
#include "rules/webgl/glslang_only_functions.h"
#include "rules/webgl/glslang_text_internal.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules::glslang_text {

// `#extension` lines for extensions the context does not offer: glslang would enable
// what the browser leaves out (dFdx in GLSL ES 1.00 code under WebGL 2, say).
void HideUnofferedExtensions(const BrowserContext& context, FileId part, std::string& text) {
  if (context.preprocessed == nullptr) return;
  for (const glsl::ExtensionDirective& directive : context.preprocessed->extensions) {
    if (directive.name == "all" || directive.range.file != part ||
        directive.range.end > text.size() ||
        model::ExtensionAvailable(directive.name, context.target, context.extensions)) {
      continue;
    }
    for (uint32_t i = directive.range.begin; i < directive.range.end; ++i) {
      if (text[i] != '\n' && text[i] != '\r') text[i] = ' ';
    }
  }
}

// `__LINE__` outside `#define` bodies, in a part the host composes behind lines of its
// own: browsers count the lines of the one text (so `#if __LINE__ < 17` tells a
// ShaderToy pass from the Common tab compiled alone), glslang those of the part, a
// source string of its own. The number is padded to the macro's width.
void ReplaceLineMacro(const BrowserContext& context, FileId part, std::string& text) {
  if (context.first_lines == nullptr || text.find("__LINE__") == std::string::npos) return;
  int64_t first_line = 1;
  for (const auto& [file, line] : *context.first_lines) {
    if (file == part) first_line = line;
  }
  if (first_line == 1) return;
  int64_t line = first_line;
  bool in_define = false;  // a #define's logical line, continued lines included
  size_t line_start = 0;
  for (size_t i = 0; i < text.size(); ++i) {
    if (i == line_start) {
      size_t newline = i - 1;  // the previous line's '\n' (i > 0 here but at the start)
      if (i > 1 && text[newline - 1] == '\r') --newline;
      const bool continued = i > 1 && newline > 0 && text[newline - 1] == '\\';
      if (!continued) {
        const size_t hash = text.find_first_not_of(" \t", i);
        const size_t word = hash == std::string::npos || text[hash] != '#'
                                ? std::string::npos
                                : text.find_first_not_of(" \t", hash + 1);
        in_define = word != std::string::npos && text.compare(word, 6, "define") == 0;
      }
    }
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
      continue;
    }
    if (in_define || !directive_text::StartsAt(text, i, "__LINE__") ||
        (i > 0 && directive_text::IsWordChar(text[i - 1])) ||
        (i + 8 < text.size() && directive_text::IsWordChar(text[i + 8]))) {
      continue;
    }
    std::string number = std::to_string(line);
    number.resize(8, ' ');
    text.replace(i, 8, number);
    i += 7;
  }
}

// Directives inside a macro's arguments (`T(\n#if A\n x\n#else\n y\n#endif\n)`):
// browsers run them, glslang stops at "unexpected '#'". In the text glslang compiles,
// within such a use the directive lines and the skipped lines become blank (line
// breaks kept), so that the arguments are what browsers passed.
void BlankDirectivesInMacroArguments(const BrowserContext& context, FileId part,
                                     std::string& text) {
  if (context.preprocessed == nullptr || context.front_end_errors) return;
  const glsl::PreprocessResult& pp = *context.preprocessed;
  const auto blank = [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end && i < text.size(); ++i) {
      if (text[i] != '\n' && text[i] != '\r') text[i] = ' ';
    }
  };
  for (const glsl::MacroUse& use : pp.macro_uses) {
    if (use.parent != glsl::kNoMacroUse || use.use.file != part || use.use.end > text.size()) {
      continue;
    }
    const size_t open = text.find('(', use.use.begin);
    if (open >= use.use.end || text.find('\n', open) >= use.use.end) continue;
    bool directives = false;
    for (size_t line = text.find('\n', open); line < use.use.end;
         line = text.find('\n', line + 1)) {
      const size_t first = text.find_first_not_of(" \t", line + 1);
      if (first >= use.use.end || text[first] != '#') continue;
      blank(first, std::min<size_t>(text.find('\n', first), use.use.end));
      directives = true;
    }
    if (!directives) continue;
    for (const SourceRange& skipped : pp.inactive_regions) {
      if (skipped.file == part && skipped.begin < use.use.end && use.use.begin < skipped.end) {
        blank(std::max<size_t>(skipped.begin, open + 1),
              std::min<size_t>(skipped.end, use.use.end));
      }
    }
  }
}

// `__FILE__`: browsers give 0, glslang wants an extension for it.
void ReplaceFileMacro(std::string& text) {
  if (text.find("__FILE__") == std::string::npos) return;
  ReplaceWord(text, "__FILE__", "0       ");
}

// An integer literal past 32 bits (4294967296, 0x100000000, a long octal), an octal
// one with a digit 8 or 9 (`08`) or a float with an empty exponent (`1e`) on a line:
// glslang's scanner reports it even in a skipped group (and then loses track of the
// group's #endif).
bool HasLiteralGlslangScansAsError(std::string_view line) {
  const auto word_char = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '.';
  };
  for (size_t i = 0; i < line.size();) {
    if (!word_char(line[i])) {
      ++i;
      continue;
    }
    size_t end = i;
    while (end < line.size() && word_char(line[end])) ++end;
    std::string_view token = line.substr(i, end - i);
    i = end;
    if (std::isdigit(static_cast<unsigned char>(token[0])) == 0) continue;
    if (!token.empty() && (token.back() == 'u' || token.back() == 'U')) token.remove_suffix(1);
    const bool hex = token.size() > 2 && token[0] == '0' && (token[1] == 'x' || token[1] == 'X');
    if (!hex && token.find_first_of(".eE") != std::string_view::npos) {
      // A float whose exponent has no digits (`1e`, `2.5E`; `1e+5` goes on past the
      // token): glslang's "bad character in float exponent".
      const size_t exponent = token.find_first_of("eE");
      if (exponent != std::string_view::npos && exponent + 1 == token.size() &&
          !(end + 1 < line.size() && (line[end] == '+' || line[end] == '-') &&
            std::isdigit(static_cast<unsigned char>(line[end + 1])) != 0)) {
        return true;
      }
      continue;
    }
    const unsigned base = hex ? 16 : (token.size() > 1 && token[0] == '0' ? 8 : 10);
    uint64_t value = 0;
    for (char c : token.substr(hex ? 2 : 0)) {
      const int digit = std::isdigit(static_cast<unsigned char>(c)) != 0 ? c - '0'
                        : std::isxdigit(static_cast<unsigned char>(c)) != 0
                            ? std::tolower(static_cast<unsigned char>(c)) - 'a' + 10
                            : -1;
      // `08`: glslang's scanner says "octal literal digit too large" even here.
      if (base == 8 && (c == '8' || c == '9')) return true;
      if (digit < 0 || static_cast<unsigned>(digit) >= base) break;  // not a literal
      value = value * base + static_cast<unsigned>(digit);
      if (value > 0xFFFFFFFFull) return true;
    }
  }
  return false;
}

// Lines inside #if groups our preprocessor skipped that hold what glslang's scanner
// trips on even there (an unterminated '"', `$`, `@`, non-ASCII bytes, an integer
// literal past 32 bits) are emptied, but for the conditional directives: browsers
// read nothing else in a skipped group (`#"` or `#define X "` there included). Only such lines:
// glslang defines some extension macros that browsers do not (say GL_OES_standard_derivatives in
// GLSL ES 3.00), so it may take a group we skip.
void EmptyInactiveLines(const BrowserContext& context, FileId part, std::string& text) {
  if (context.preprocessed == nullptr) return;
  for (const SourceRange& region : context.preprocessed->inactive_regions) {
    if (region.file != part || region.end > text.size()) continue;
    size_t line = region.begin;
    while (line < region.end) {
      size_t end = text.find('\n', line);
      if (end == std::string::npos || end > region.end) end = region.end;
      const size_t first = text.find_first_not_of(" \t", line);
      const bool troubling =
          std::any_of(text.begin() + static_cast<std::ptrdiff_t>(line),
                      text.begin() + static_cast<std::ptrdiff_t>(end), [](char c) {
                        return c == '"' || c == '\'' || c == '$' || c == '@' || c == '`' ||
                               static_cast<unsigned char>(c) >= 0x80;
                      });
      const bool oversized = !troubling && HasLiteralGlslangScansAsError(
                                               std::string_view(text).substr(line, end - line));
      // Conditional directives stay: glslang follows them to find the group's end.
      const std::string_view keyword =
          directive_text::DirectiveKeyword(std::string_view(text).substr(line, end - line));
      const bool conditional = first < end && text[first] == '#' &&
                               (keyword == "if" || keyword == "ifdef" || keyword == "ifndef" ||
                                keyword == "elif" || keyword == "else" || keyword == "endif");
      if ((troubling || oversized) && first < end && !conditional) {
        for (size_t i = line; i < end; ++i) {
          if (text[i] != '\r' && text[i] != '\\') text[i] = ' ';
        }
      }
      line = end + 1;
    }
  }
}

// A `#define` whose body holds a number glslang's scanner rejects (`1e`, `08`, a
// literal past 32 bits) and that nothing uses: browsers read a macro's body only where
// it is expanded, glslang scans it at the definition. The body is emptied (a used macro
// stays, and both report the number where it is used). One line bodies only.
void EmptyUnusedMacroBodiesGlslangRejects(const BrowserContext& context, FileId part,
                                          std::string& text) {
  if (context.preprocessed == nullptr) return;
  const glsl::PreprocessResult& pp = *context.preprocessed;
  directive_text::ForEachLine(std::string_view(text), [&](std::string_view line, size_t begin) {
    const auto define = directive_text::ParseDefine(line);
    if (!define) return;
    size_t body = define->name_end;
    if (define->function_like) {
      body = line.find(')', body);
      if (body == std::string_view::npos) return;
      ++body;
    }
    std::string_view rest = line.substr(body);
    if (!rest.empty() && rest.back() == '\r') rest.remove_suffix(1);
    if (rest.empty() || rest.back() == '\\' || !HasLiteralGlslangScansAsError(rest)) return;
    const bool used =
        std::any_of(pp.macro_uses.begin(), pp.macro_uses.end(),
                    [&](const glsl::MacroUse& use) { return use.name == define->name; });
    const bool skipped = std::any_of(
        pp.inactive_regions.begin(), pp.inactive_regions.end(),
        [&](const SourceRange& r) { return r.file == part && r.begin <= begin && begin < r.end; });
    if (used || skipped) return;
    for (size_t i = begin + body; i < begin + body + rest.size(); ++i) text[i] = ' ';
  });
}

// Macro uses that glslang expands differently from browsers, replaced on their line
// by the expansion our preprocessor (which follows the browser) made: `F()` passes one
// empty argument in browsers, where glslang stops with "Too few args in Macro"; a
// function-like macro that names itself in its body (`#define line(a) line(a, z)`) is
// not expanded again in browsers, where glslang counts the inner call's arguments
// against the macro. Only uses written in `part` itself, outside other macros, and
// only when our front end found no error there.
// A function-like macro that names itself in its body (`#define normalize(x)
// normalize(x + 1e-6)`), defined and used only in `part` (a use inside another macro's
// arguments or body included, where its name is spelled) and named by no other
// directive there: the macro and its uses get a same-length alias, so that glslang,
// like a browser, reads the name in the body as the function it is (a built-in or the
// shader's own) and never as the macro again. Returns the macros renamed.
// Whether the name at `at` in a directive line means the macro: after `#undef`,
// `#ifdef`, `#ifndef` or `defined`, or called (`NAME (`) in another macro's body.
bool NamesTheMacro(std::string_view directive, size_t at, size_t length) {
  size_t after = at + length;
  while (after < directive.size() && (directive[after] == ' ' || directive[after] == '\t')) ++after;
  if (after < directive.size() && directive[after] == '(') return true;
  size_t keyword_end = at;
  while (keyword_end > 0 &&
         (directive[keyword_end - 1] == ' ' || directive[keyword_end - 1] == '\t' ||
          directive[keyword_end - 1] == '(')) {
    --keyword_end;
  }
  size_t keyword_begin = keyword_end;
  while (keyword_begin > 0 && directive_text::IsWordChar(directive[keyword_begin - 1]))
    --keyword_begin;
  const std::string_view keyword = directive.substr(keyword_begin, keyword_end - keyword_begin);
  return keyword == "undef" || keyword == "ifdef" || keyword == "ifndef" || keyword == "defined";
}

std::set<std::string> RenameSelfNamingMacros(const BrowserContext& context, FileId part,
                                             std::string_view original, std::string& text) {
  const glsl::PreprocessResult& pp = *context.preprocessed;
  // The unit's texts as written: a macro of ShaderToy's Common may be used in the pass.
  const auto original_of = [&](FileId file) {
    return file == part ? original : OriginalText(context, file);
  };
  // Function-like macros of the unit whose body names the macro itself.
  std::set<std::string> self_naming;
  std::set<std::pair<FileId, uint32_t>> definitions_read;
  for (const glsl::MacroUse& use : pp.macro_uses) {
    const SourceRange& at = use.definition;
    const std::string_view defined_in = original_of(at.file);
    if (at.end >= defined_in.size() || defined_in[at.end] != '(' ||
        self_naming.contains(use.name) || !definitions_read.insert({at.file, at.begin}).second) {
      continue;
    }
    size_t end = at.end;
    while (end < defined_in.size() && defined_in[end] != '\n') {
      end += (defined_in[end] == '\\' && end + 1 < defined_in.size()) ? 2 : 1;
    }
    const size_t body = defined_in.find(')', at.end);
    if (body == std::string_view::npos || body >= end) continue;
    if (directive_text::ContainsWord(defined_in.substr(body + 1, end - body - 1), use.name)) {
      self_naming.insert(use.name);
    }
  }
  // An alias must be new to every part, and the same in each of them.
  const std::string unit_text = UnitText(context, original);
  std::set<std::string> renamed;
  for (const std::string& name : self_naming) {
    bool movable = true;
    std::vector<SourceRange> names;  // the definition's and every use's name
    for (const glsl::MacroUse& use : pp.macro_uses) {
      if (use.name != name) continue;
      const std::string_view used_in = original_of(use.use.file);
      movable = movable && !original_of(use.definition.file).empty() &&
                use.use.begin + name.size() <= used_in.size() &&
                used_in.substr(use.use.begin, name.size()) == name;
      names.push_back(
          {use.use.file, use.use.begin, use.use.begin + static_cast<uint32_t>(name.size())});
      names.push_back(use.definition);
    }
    const std::string whole(original);
    if (!movable) continue;
    const std::string alias = SameLengthAlias(unit_text, name);
    if (alias.empty()) continue;
    std::set<uint32_t> done;
    for (const SourceRange& range : names) {
      if (range.file != part || range.end > text.size() || !done.insert(range.begin).second ||
          text.compare(range.begin, name.size(), name) != 0) {
        continue;
      }
      text.replace(range.begin, alias.size(), alias);
    }
    // The directives that name the macro name the alias: `#undef NAME`, `#ifdef NAME`,
    // `#ifndef NAME`, `defined(NAME)`, and calls of it in other macros' bodies (its own
    // body calls the function, which keeps the name).
    directive_text::ForEachLine(whole, [&](std::string_view directive, size_t line_begin) {
      if (directive_text::DirectiveKeyword(directive).empty()) return;
      const auto define = directive_text::ParseDefine(directive);
      if (define && define->function_like && define->name == name) return;  // renamed above
      directive_text::ForEachIdentifier(directive, [&](std::string_view word, size_t at) {
        if (word != name || !NamesTheMacro(directive, at, name.size())) return;
        at += line_begin;
        if (at + name.size() <= text.size() && text.compare(at, name.size(), name) == 0) {
          text.replace(at, alias.size(), alias);
        }
      });
    });
    renamed.insert(name);
  }
  return renamed;
}

void ExpandMacroUses(const BrowserContext& context, FileId part, std::string_view original,
                     std::string& text) {
  if (context.preprocessed == nullptr || context.tree == nullptr || context.front_end_errors) {
    return;
  }
  const std::set<std::string> renamed = RenameSelfNamingMacros(context, part, original, text);
  // `F()`, and any use with an empty argument (`M(h, 2, )`): glslang also trips on the
  // empty argument once the macro's body passes it on to another macro.
  const glsl::PreprocessResult& pp = *context.preprocessed;
  // The tokens of each top-level macro use of the part, by where the use is spelled.
  std::map<std::pair<uint32_t, uint32_t>, std::vector<std::string_view>> expansions;
  for (const glsl::PpToken& token : pp.tokens) {
    if (token.macro_use != glsl::kNoMacroUse && token.expansion.file == part &&
        token.kind != glsl::TokenKind::kEndOfFile) {
      expansions[{token.expansion.begin, token.expansion.end}].push_back(token.text);
    }
  }
  struct Replacement {
    SourceRange range;
    std::vector<std::string_view> tokens;
    std::string self;  // the macro's name when its body names itself
  };
  std::vector<Replacement> replacements;
  std::map<std::string, std::string> aliases;  // macro naming itself -> alias
  for (const glsl::MacroUse& use : pp.macro_uses) {
    if (use.parent != glsl::kNoMacroUse || use.use.file != part || use.use.end > original.size()) {
      continue;
    }
    const std::string spelled(original.substr(use.use.begin, use.use.end - use.use.begin));
    if (spelled.find('\n') != std::string::npos || spelled.find('(') == std::string::npos ||
        renamed.contains(use.name)) {
      continue;
    }
    Replacement replacement{use.use, {}, {}};
    if (const auto tokens = expansions.find({use.use.begin, use.use.end});
        tokens != expansions.end()) {
      replacement.tokens = tokens->second;
      for (const std::string_view token : replacement.tokens) {
        if (token == use.name) replacement.self = use.name;
      }
    }
    if (replacement.self.empty() && !directive_text::IsEmptyCall(spelled) &&
        !directive_text::HasEmptyArgument(spelled)) {
      continue;
    }
    if (!replacement.self.empty() && !aliases.contains(use.name)) {
      aliases[use.name] = SameLengthAlias(std::string(original), use.name);
    }
    replacements.push_back(std::move(replacement));
  }
  // A function that a macro of the same name calls (`#define line(a) line(a, z)`) gets
  // the alias: glslang would take every later `line(` for the macro again.
  glsl::VisitPreorder(*context.tree, [&](const glsl::Node& node, uint32_t) {
    const auto* function = node.As<glsl::FunctionDeclaration>();
    if (function == nullptr) return true;
    const auto alias = aliases.find(function->name.text);
    const SourceRange& range = function->name.range;
    if (alias != aliases.end() && !alias->second.empty() && range.file == part &&
        range.end <= text.size() &&
        text.compare(range.begin, function->name.text.size(), function->name.text) == 0) {
      text.replace(range.begin, alias->second.size(), alias->second);
    }
    return false;
  });
  // From the end, so that earlier offsets stay valid.
  std::sort(replacements.begin(), replacements.end(),
            [](const auto& a, const auto& b) { return a.range.begin > b.range.begin; });
  for (const Replacement& replacement : replacements) {
    // Only a self-named token that is called needs the alias: glslang would take
    // `T(` for the macro again, while `T = ...` (a variable of the macro's name) is
    // plain text to it. No alias to give (a one-letter name): glslang keeps its say.
    std::string expansion = " ";
    bool aliased = true;
    for (size_t i = 0; i < replacement.tokens.size(); ++i) {
      const std::string_view token = replacement.tokens[i];
      const bool called = i + 1 < replacement.tokens.size() && replacement.tokens[i + 1] == "(";
      const bool self = !replacement.self.empty() && token == replacement.self && called;
      const std::string& alias = self ? aliases[replacement.self] : replacement.self;
      aliased = aliased && (!self || !alias.empty());
      expansion += std::string(self ? std::string_view(alias) : token) + " ";
    }
    if (!aliased) continue;
    text.replace(replacement.range.begin, replacement.range.end - replacement.range.begin,
                 expansion);
  }
}

// Lines of `text` (offsets of their starts), and which are inside a block comment.
struct TextLines {
  std::vector<size_t> starts;
  std::vector<bool> in_comment;  // the line starts inside a /* */ comment
};

TextLines LinesOf(const std::string& text) {
  TextLines lines{{0}, {false}};
  bool block = false;
  for (size_t i = 0; i < text.size(); ++i) {
    if (!block && directive_text::StartsAt(text, i, "//")) {
      while (i + 1 < text.size() && text[i + 1] != '\n') ++i;
    } else if (!block && directive_text::StartsAt(text, i, "/*")) {
      block = true;
      ++i;
    } else if (block && directive_text::StartsAt(text, i, "*/")) {
      block = false;
      ++i;
    } else if (text[i] == '\n') {
      lines.starts.push_back(i + 1);
      lines.in_comment.push_back(block);
    }
  }
  return lines;
}

// `#define NAME(PARAMETER) BODY`: NAME and BODY.
struct OneParameterMacro {
  std::string_view name;
  std::string_view body;
};
std::optional<OneParameterMacro> OneParameterDefine(std::string_view line) {
  const auto define = directive_text::ParseDefine(line);
  if (!define || !define->function_like) return std::nullopt;
  const auto blank = [&](size_t at) {
    while (at < line.size() && (line[at] == ' ' || line[at] == '\t')) ++at;
    return at;
  };
  const size_t parameter = blank(define->name_end + 1);
  if (parameter >= line.size() || directive_text::IsWordChar(line[parameter]) == false ||
      (line[parameter] >= '0' && line[parameter] <= '9')) {
    return std::nullopt;
  }
  size_t parameter_end = parameter;
  while (parameter_end < line.size() && directive_text::IsWordChar(line[parameter_end])) {
    ++parameter_end;
  }
  const size_t close = blank(parameter_end);
  if (close >= line.size() || line[close] != ')') return std::nullopt;
  return OneParameterMacro{define->name, line.substr(close + 1)};
}

// Calls `call(name, begin, end)` for each `NAME()` (blanks allowed) in `text`.
template <typename Callback>
void ForEachEmptyCall(std::string_view text, Callback&& call) {
  directive_text::ForEachIdentifier(text, [&](std::string_view name, size_t at) {
    size_t next = at + name.size();
    while (next < text.size() && (text[next] == ' ' || text[next] == '\t')) ++next;
    if (next >= text.size() || text[next] != '(') return;
    ++next;
    while (next < text.size() && (text[next] == ' ' || text[next] == '\t')) ++next;
    if (next < text.size() && text[next] == ')') call(name, at, next + 1);
  });
}

// `F()` in the body of a `#define`, F a one-parameter macro of this part: browsers pass
// one empty argument, glslang counts none ("Too few args in Macro F"). Such uses become
// `F(E)`, E a macro defined empty on a blank (or comment) line before the first of them (glslang
// expands an argument before substituting it, so F's body gets nothing, as in
// browsers); line numbers stay.
void PassEmptyArgumentsInMacroBodies(const BrowserContext& context, FileId part,
                                     std::string_view original, std::string& text,
                                     std::string& prelude) {
  if (context.preprocessed == nullptr || context.front_end_errors ||
      text.find("()") == std::string::npos) {
    return;
  }
  const TextLines lines = LinesOf(text);
  const auto line_text = [&](size_t line) {
    const size_t begin = lines.starts[line];
    const size_t end = line + 1 < lines.starts.size() ? lines.starts[line + 1] - 1 : text.size();
    return text.substr(begin, end - begin);
  };
  const auto continued = [&](size_t line) {
    std::string body = line_text(line);
    while (!body.empty() && (body.back() == '\r' || body.back() == ' ')) body.pop_back();
    return !body.empty() && body.back() == '\\';
  };
  // One-parameter macros whose body pastes no tokens, and the lines of #define bodies.
  std::set<std::string> one_parameter;
  std::vector<bool> define_body(lines.starts.size(), false);
  for (size_t line = 0; line < lines.starts.size(); ++line) {
    const std::string first = line_text(line);
    if (lines.in_comment[line] || first.find('#') == std::string::npos) continue;
    const auto one = OneParameterDefine(first);
    const bool define = one.has_value();
    if (!define && !directive_text::IsDirective(first, "define")) continue;
    std::string body = define ? std::string(one->body) : first;
    size_t last = line;
    define_body[line] = true;
    while (continued(last) && last + 1 < lines.starts.size()) {
      ++last;
      define_body[last] = true;
      body += line_text(last);
    }
    if (define && body.find("##") == std::string::npos)
      one_parameter.insert(std::string(one->name));
    line = last;
  }
  if (one_parameter.empty()) return;
  std::vector<size_t> with_empty_calls;
  for (size_t line = 0; line < lines.starts.size(); ++line) {
    if (!define_body[line]) continue;
    bool found = false;
    ForEachEmptyCall(line_text(line), [&](std::string_view name, size_t, size_t) {
      found = found || one_parameter.contains(std::string(name));
    });
    if (found) with_empty_calls.push_back(line);
  }
  if (with_empty_calls.empty()) return;
  // A blank line before them, outside comments, skipped groups and continued lines.
  const TextLines original_lines = LinesOf(std::string(original));
  const auto skipped = [&](size_t line) {
    if (line >= original_lines.starts.size()) return true;
    const size_t at = original_lines.starts[line];
    return std::any_of(context.preprocessed->inactive_regions.begin(),
                       context.preprocessed->inactive_regions.end(), [&](const SourceRange& r) {
                         return r.file == part && r.begin <= at && at < r.end;
                       });
  };
  // A line holding only a `//` comment does too (glslang does not need the comment).
  std::optional<size_t> blank;
  for (size_t line = 0; line < with_empty_calls.front(); ++line) {
    const std::string content = line_text(line);
    const size_t first = content.find_first_not_of(" \t\r");
    const bool free = first == std::string::npos || content.compare(first, 2, "//") == 0;
    if (free && !lines.in_comment[line] && (line == 0 || !continued(line - 1)) && !skipped(line) &&
        content.find('\\') == std::string::npos) {
      blank = line;
    }
  }
  // Without one, behind the site's header, the definition goes before the part.
  if (!blank && !context.behind_header) return;
  std::string empty = "SPE";
  for (int n = 0; text.find(empty) != std::string::npos; ++n) empty = "SPE" + std::to_string(n);
  // From the last line, so that earlier line starts stay valid.
  for (auto line = with_empty_calls.rbegin(); line != with_empty_calls.rend(); ++line) {
    const std::string body = line_text(*line);
    std::string rewritten;
    size_t copied = 0;
    ForEachEmptyCall(body, [&](std::string_view name, size_t begin, size_t end) {
      if (!one_parameter.contains(std::string(name))) return;
      rewritten += body.substr(copied, begin - copied) + std::string(name) + "(" + empty + ")";
      copied = end;
    });
    rewritten += body.substr(copied);
    text.replace(lines.starts[*line], body.size(), rewritten);
  }
  const std::string definition = "#define " + empty;
  if (blank) {
    text.replace(lines.starts[*blank], line_text(*blank).size(), definition);
  } else {
    prelude += definition + "\n";
  }
}

// A `//` comment whose line ends in a backslash continues on the next line in
// browsers (GLSL ES 3.00 section 3.2 joins lines before comments are removed); glslang
// ends the comment at the line break and compiles the next line as code, where it may
// stop at a syntax error that hides the shader's real ones. The backslash and the
// continued text become spaces, on the same lines.
void BlankContinuedLineComments(std::string& text) {
  if (text.find('\\') == std::string::npos) return;  // nothing continues a line
  bool block = false;
  for (size_t i = 0; i < text.size(); ++i) {
    if (block) {
      if (directive_text::StartsAt(text, i, "*/")) block = false, ++i;
      continue;
    }
    if (directive_text::StartsAt(text, i, "/*")) {
      block = true;
      ++i;
      continue;
    }
    if (!directive_text::StartsAt(text, i, "//")) continue;
    // To the end of the comment: line breaks after a backslash do not end it.
    size_t end = i;
    bool continued = false;
    while (end < text.size() && text[end] != '\n') {
      if (text[end] == '\\') {
        size_t next = end + 1;
        if (next < text.size() && text[next] == '\r') ++next;
        if (next < text.size() && text[next] == '\n') {
          continued = true;
          text[end] = ' ';
          end = next + 1;
          continue;
        }
      }
      if (continued) text[end] = text[end] == '\r' ? '\r' : ' ';
      ++end;
    }
    i = end;
  }
}

// A backslash at the end of a line continues it in browsers whatever the GLSL ES
// version; glslang allows that in GLSL ES 3.00 only. In GLSL ES 1.00 code each
// continued line is joined onto its first line and the line breaks follow it, so that
// every later line keeps its number.
std::string JoinContinuedLines(const BrowserContext& context, const std::string& text) {
  if (context.version >= 300 || text.find('\\') == std::string::npos) return text;
  std::string out;
  out.reserve(text.size());
  size_t pending_breaks = 0;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\\') {
      size_t next = i + 1;
      if (next < text.size() && text[next] == '\r') ++next;
      if (next < text.size() && text[next] == '\n') {
        ++pending_breaks;
        i = next;
        continue;
      }
    }
    if (c == '\n') out.append(pending_breaks, '\n'), pending_breaks = 0;
    out += c;
  }
  out.append(pending_breaks, '\n');
  return out;
}

// `#define` lines that browsers (ANGLE's preprocessor) accept and glslang's does not,
// written as glslang understands them, on the same line: a body right after an
// object-like macro's name (`#define EPS.001`: glslang drops the macro) gets a space,
// a trailing comma in a parameter list (`#define f(a, b,)`) goes.
// Object-like macros of the unit whose body is one unsigned literal (`#define N 64u`,
// `#define N (26u)`) outside skipped groups, by name, with the literal's value as
// glslang's `#if` takes it ("64"); a name defined with two values is left out.
std::map<std::string, std::string> UnsignedLiteralMacros(const BrowserContext& context,
                                                         const SourceFile& part) {
  std::map<std::string, std::string> values;
  std::set<std::string> ambiguous;
  const auto skipped = [&](FileId file, size_t at) {
    return context.preprocessed != nullptr &&
           std::any_of(context.preprocessed->inactive_regions.begin(),
                       context.preprocessed->inactive_regions.end(), [&](const SourceRange& r) {
                         return r.file == file && r.begin <= at && at < r.end;
                       });
  };
  const auto scan = [&](const SourceFile& file) {
    const std::string_view text = file.Text();
    if (text.find("define") == std::string_view::npos) return;
    directive_text::ForEachLine(text, [&](std::string_view line, size_t line_begin) {
      auto define = directive_text::ParseUnsignedDefine(line);
      if (!define || skipped(file.Id(), line_begin)) return;
      const auto [at, added] = values.emplace(define->name, define->value);
      if (!added && at->second != define->value) ambiguous.insert(at->first);
    });
  };
  scan(part);
  for (const SourceFile* unit_part : context.parts) {
    if (unit_part->Id() != part.Id()) scan(*unit_part);
  }
  for (const std::string& name : ambiguous) values.erase(name);
  return values;
}

// `unsigned_macros` is called at the first `#if` or `#elif` line, if any.
std::string RepairDefines(
    const std::string& text,
    const std::function<std::map<std::string, std::string>()>& unsigned_macros) {
  std::optional<std::map<std::string, std::string>> macros;
  std::string out;
  out.reserve(text.size() + 16);
  directive_text::ForEachLine(text, [&](std::string_view spelled, size_t line_begin) {
    if (line_begin > 0) out += '\n';
    if (spelled.find('#') == std::string_view::npos) {
      out += spelled;
      return;
    }
    if (directive_text::IsIfOrElif(spelled)) {
      // `#if N % 2u`: browsers take unsigned literals in #if, glslang does not; nor
      // through a macro (`#define N 64u`, `#if N == 64u`), whose value goes in its place.
      const std::string line = directive_text::WithoutUnsignedSuffixes(spelled);
      if (!macros) macros = unsigned_macros();
      size_t copied = 0;
      directive_text::ForEachIdentifier(line, [&](std::string_view word, size_t at) {
        const auto value = macros->find(std::string(word));
        if (value == macros->end()) return;
        out.append(line, copied, at - copied);
        out += value->second;
        copied = at + word.size();
      });
      out.append(line, copied);
      return;
    }
    const auto define = directive_text::ParseDefine(spelled);
    if (!define) {
      out += spelled;
      return;
    }
    std::string rest(spelled.substr(define->name_end));
    if (!rest.empty() && rest[0] == '(') {
      const size_t close = rest.find(')');
      const size_t last =
          close == std::string::npos ? close : rest.find_last_not_of(" \t", close - 1);
      if (last != std::string::npos && last > 0 && rest[last] == ',') rest[last] = ' ';
    } else if (!rest.empty() && rest[0] != ' ' && rest[0] != '\t' && rest[0] != '\r') {
      rest.insert(0, " ");
    }
    out += spelled.substr(0, define->name_end);
    out += rest;
  });
  return out;
}

}  // namespace shaderport::rules::glslang_text

namespace shaderport::rules {

GlslangText TextForGlslang(const BrowserContext& context, const SourceFile& part) {
  using namespace glslang_text;  // NOLINT(google-build-using-namespace): its steps, in order
  std::string text(part.Text());
  std::string prelude;
  // Same-length edits first: the offsets of our front end stay valid for the next.
  RenameDeclarableBuiltins(context, part.Id(), text);
  RenameGlslangOnlyKeywords(context, part.Id(), text);
  RenameLengthFields(context, part.Id(), text);
  ReplaceFileMacro(text);
  ReplaceLineMacro(context, part.Id(), text);
  BlankDirectivesInMacroArguments(context, part.Id(), text);
  HideUnofferedExtensions(context, part.Id(), text);
  BlankContinuedLineComments(text);
  EmptyInactiveLines(context, part.Id(), text);
  EmptyUnusedMacroBodiesGlslangRejects(context, part.Id(), text);
  ExpandMacroUses(context, part.Id(), part.Text(), text);
  PassEmptyArgumentsInMacroBodies(context, part.Id(), part.Text(), text, prelude);
  text = RepairDefines(JoinContinuedLines(context, text),
                       [&] { return UnsignedLiteralMacros(context, part); });
  if (text == part.Text()) text.clear();
  return {std::move(text), std::move(prelude)};
}

std::string ExpandedTextForGlslang(const BrowserContext& context, const SourceFile& part) {
  std::vector<std::string> lines(part.LineCount());
  for (uint32_t line = 1; line <= part.LineCount(); ++line) {
    const std::string_view text = part.LineText(line);
    const size_t hash = text.find_first_not_of(" \t");
    if (hash == std::string_view::npos || text[hash] != '#') continue;
    const size_t word = text.find_first_not_of(" \t", hash + 1);
    const std::string_view directive = word == std::string_view::npos ? "" : text.substr(word);
    if (directive.starts_with("version") || directive.starts_with("extension")) {
      lines[line - 1] = std::string(text);
    }
  }
  if (context.preprocessed != nullptr) {
    for (const glsl::PpToken& token : context.preprocessed->tokens) {
      if (token.kind == glsl::TokenKind::kEndOfFile || token.expansion.file != part.Id()) continue;
      const uint32_t line = part.LocationOf(token.expansion.begin).line;
      if (line == 0 || line > lines.size()) continue;
      std::string& out = lines[line - 1];
      if (!out.empty()) out += ' ';
      out += token.text;
    }
  }
  std::string text;
  for (size_t i = 0; i < lines.size(); ++i) {
    if (i != 0) text += '\n';
    text += lines[i];
  }
  return text;
}

}  // namespace shaderport::rules
