#include "glsl/lex/macro_definitions.h"

#include <string>

#include "glsl/lex/lexer.h"

namespace shaderport::glsl {
namespace {

SourceRange RangeOf(const SourceFile& file, const Token& t) { return {file.Id(), t.begin, t.end}; }

bool SameDefinition(const Macro& a, const Macro& b) {
  if (a.function_like != b.function_like || a.params != b.params ||
      a.body.size() != b.body.size()) {
    return false;
  }
  for (size_t i = 0; i < a.body.size(); ++i) {
    if (a.body[i].text != b.body[i].text) return false;
    if (i > 0 && a.body[i].leading_space != b.body[i].leading_space) return false;
  }
  return true;
}

// Reads "( a, b )" after a function-like macro's name; returns tokens used, 0 on error.
size_t ParseParams(PpState& state, const SourceFile& file, std::span<const Token> line,
                   Macro* macro) {
  size_t i = 1;  // line[0] is '('
  if (i < line.size() && line[i].punct == Punct::kRightParen) return i + 1;
  while (i < line.size()) {
    const Token& name = line[i];
    if (name.kind != TokenKind::kIdentifier) break;
    for (std::string_view p : macro->params) {
      if (p == name.text) {
        state.Report(Severity::kError, "preprocessor/invalid-define", RangeOf(file, name),
                     "macro parameter '" + std::string(name.text) + "' appears twice");
        return 0;
      }
    }
    macro->params.push_back(name.text);
    if (++i >= line.size()) break;
    if (line[i].punct == Punct::kRightParen) return i + 1;
    if (line[i].punct != Punct::kComma) break;
    ++i;
  }
  const SourceRange at = i < line.size() ? RangeOf(file, line[i]) : RangeOf(file, line[0]);
  state.Report(Severity::kError, "preprocessor/invalid-define", at,
               "expected a parameter name, ',' or ')' in the macro parameter list");
  return 0;
}

// ESSL reserves "defined" and names starting with GL_ (ESSL 3.00 section 3.4); names with
// "__" are only reserved for the implementation, so they get a warning (as ANGLE does).
bool CheckName(PpState& state, std::string_view name, SourceRange at, bool undef) {
  const char* verb = undef ? "undefined" : "defined";
  if (const Macro* m = state.Find(name); m && m->predefined) {
    state.Report(Severity::kError, "preprocessor/predefined-macro", at,
                 "predefined macro '" + std::string(name) + "' cannot be " + verb);
    return false;
  }
  if (name == "defined" || name.starts_with("GL_")) {
    state.Report(Severity::kError, "preprocessor/reserved-macro-name", at,
                 "macro name '" + std::string(name) + "' is reserved and cannot be " + verb);
    return false;
  }
  if (!undef && name.find("__") != std::string_view::npos) {
    state.Report(Severity::kWarning, "preprocessor/double-underscore-macro-name", at,
                 "macro names containing '__' are reserved for the implementation");
  }
  return true;
}

}  // namespace

void DefineMacro(PpState& state, const SourceFile& file, std::span<const Token> line,
                 SourceRange directive) {
  if (line.empty() || line[0].kind != TokenKind::kIdentifier) {
    state.Report(Severity::kError, "preprocessor/invalid-define",
                 line.empty() ? directive : RangeOf(file, line[0]),
                 "#define must be followed by a macro name");
    return;
  }
  Macro macro;
  macro.name = std::string(line[0].text);
  macro.definition = RangeOf(file, line[0]);
  size_t i = 1;
  if (line.size() > 1 && line[1].punct == Punct::kLeftParen && !line[1].leading_space) {
    macro.function_like = true;
    const size_t used = ParseParams(state, file, line.subspan(1), &macro);
    if (used == 0) return;
    i += used;
  }
  for (; i < line.size(); ++i) {
    PpToken t = ToPpToken(file, line[i], state);
    int param = -1;
    for (size_t p = 0; p < macro.params.size() && t.kind == TokenKind::kIdentifier; ++p) {
      if (macro.params[p] == t.text) param = static_cast<int>(p);
    }
    macro.body.push_back(t);
    macro.body_param.push_back(param);
  }
  if (!macro.body.empty() && (macro.body.front().punct == Punct::kHashHash ||
                              macro.body.back().punct == Punct::kHashHash)) {
    state.Report(Severity::kError, "preprocessor/invalid-define", directive,
                 "'##' cannot appear at either end of a macro body");
    return;
  }
  if (!CheckName(state, macro.name, macro.definition, false)) return;
  if (const Macro* old = state.Find(macro.name)) {
    if (!SameDefinition(*old, macro)) {
      state.Report(Severity::kError, "preprocessor/macro-redefined", macro.definition,
                   "macro '" + macro.name + "' is redefined with a different body");
      state.result.diagnostics.back().notes.push_back(
          {old->definition, "previous definition is here"});
    }
    return;
  }
  std::string name = macro.name;
  state.NoteMacroName(name);
  state.macros.emplace(std::move(name), std::move(macro));
}

void UndefineMacro(PpState& state, const SourceFile& file, std::span<const Token> line,
                   SourceRange directive) {
  if (line.empty() || line[0].kind != TokenKind::kIdentifier) {
    state.Report(Severity::kError, "preprocessor/invalid-define",
                 line.empty() ? directive : RangeOf(file, line[0]),
                 "#undef must be followed by a macro name");
    return;
  }
  if (!CheckName(state, line[0].text, RangeOf(file, line[0]), true)) return;
  if (line.size() > 1) {
    state.Report(Severity::kWarning, "preprocessor/extra-tokens", RangeOf(file, line[1]),
                 "extra tokens after the macro name of #undef are ignored");
  }
  if (auto it = state.macros.find(line[0].text); it != state.macros.end()) {
    state.macros.erase(it);
  }
}

void AddPredefinedMacros(PpState& state, std::span<const std::string> predefined) {
  auto add = [&](std::string_view name, BuiltinMacro builtin, std::string_view value,
                 bool builtin_name = true) {
    Macro m;
    m.name = std::string(name);
    m.predefined = builtin_name;
    m.builtin = builtin;
    if (!value.empty()) {
      const std::string_view stored = state.Store(std::string(value));
      const SourceFile scratch(kNoFile, "<predefined>", std::string(stored));
      const LexedFile lexed = Lex(scratch);
      for (const Token& t : lexed.tokens) {
        if (t.kind == TokenKind::kEndOfFile) break;
        PpToken pp;
        pp.kind = t.kind;
        pp.punct = t.punct;
        pp.text = stored.substr(t.begin, t.end - t.begin);
        // Logical spelling, as for tokens of a file (the parser reads texts as they are).
        if (pp.text.find('\\') != std::string_view::npos) {
          pp.text = StoreLogicalSpelling(pp.text, state);
        }
        pp.leading_space = t.leading_space;
        m.body.push_back(pp);  // spelling stays invalid: uses point at the macro name
        m.body_param.push_back(-1);
      }
    }
    state.NoteMacroName(m.name);
    state.macros.insert_or_assign(m.name, std::move(m));
  };
  add("__LINE__", BuiltinMacro::kLine, "");
  add("__FILE__", BuiltinMacro::kFile, "");
  add("__VERSION__", BuiltinMacro::kVersion, "");
  add("GL_ES", BuiltinMacro::kNone, "1");
  for (const std::string& spec : predefined) {
    const size_t eq = spec.find('=');
    const std::string_view name = std::string_view(spec).substr(0, eq);
    const std::string_view value =
        eq == std::string::npos ? std::string_view("1") : std::string_view(spec).substr(eq + 1);
    // A harness's own macros (ShaderToy's HW_PERFORMANCE) are #define lines of its
    // header: code may #undef them, as on the site.
    add(name, BuiltinMacro::kNone, value, false);
  }
}

}  // namespace shaderport::glsl
