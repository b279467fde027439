// The names glslang and browsers disagree on, renamed in glslang's text at the same
// length (TextForGlslang, glslang_divergence.h): built-ins a shader may declare, words
// only glslang reserves, struct fields named `length`.
#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <span>
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

// Names of GLSL ES 3.00 built-ins that browsers still let a shader declare as its own
// function: ANGLE counts a name as a built-in only when none of its overloads needs an
// extension the shader did not enable (OES_EGL_image_external_essl3, EXT_YUV_target and
// the like). Measured in Chromium 156 for every built-in name, no extension enabled.
constexpr std::array<std::string_view, 6> kEs3DeclarableBuiltins = {
    "mix", "texelFetch", "texture", "textureGrad", "textureLod", "textureSize"};

// A name glslang has as a built-in function here and browsers do not.
bool GlslangOnlyFunctionName(const BrowserContext& context, std::string_view name) {
  return webgl::IsGlslangOnlyFunction(name, context.version, context.preprocessed);
}

bool SameParameters(const glsl::BuiltinFunction& builtin, const glsl::Symbol& function) {
  if (builtin.params.size() != function.parameters.size()) return false;
  for (size_t i = 0; i < builtin.params.size(); ++i) {
    if (!(builtin.params[i].type == function.parameters[i])) return false;
  }
  return true;
}

// A user function with a built-in's name that the browser accepts: in GLSL ES 1.00 an
// overload with parameters no built-in of that name has (the same ones redefine it, an
// error); in GLSL ES 3.00 a name that is no built-in in this stage or is listed above;
// in both, a name only glslang has.
bool BrowserAcceptsName(const BrowserContext& context, const glsl::Symbol& function) {
  if (GlslangOnlyFunctionName(context, function.name)) return true;
  const model::Stage stage = context.stage;
  const int version = context.version >= 300 ? 300 : 100;
  bool builtin_here = false;
  for (const glsl::BuiltinFunction* builtin : glsl::BuiltinOverloadList(function.name)) {
    if (!builtin->AvailableIn(version, stage) || !builtin->extension.empty()) continue;
    builtin_here = true;
    if (version < 300 && SameParameters(*builtin, function)) return false;
  }
  if (!builtin_here) return false;  // glslang has no quarrel with the name
  return version < 300 || std::find(kEs3DeclarableBuiltins.begin(), kEs3DeclarableBuiltins.end(),
                                    function.name) != kEs3DeclarableBuiltins.end();
}

// The text of `file` as written: one of the unit's parts (ShaderToy: Common, the pass)
// or the user's file; empty for any other.
std::string_view OriginalText(const BrowserContext& context, FileId file) {
  for (const SourceFile* unit_part : context.parts) {
    if (unit_part->Id() == file) return unit_part->Text();
  }
  return context.file != nullptr && file == context.file->Id() ? context.file->Text()
                                                               : std::string_view();
}

// Every part's text, for aliases that must be new to all of them; `text` when the
// caller named no parts.
std::string UnitText(const BrowserContext& context, std::string_view text) {
  if (context.parts.empty()) return std::string(text);
  std::string unit;
  for (const SourceFile* unit_part : context.parts) unit += unit_part->Text();
  return unit;
}

// A name of `name`'s length that neither `text` nor `taken` contains: its last
// characters replaced by digits (no `__`, no `gl_` prefix: both reserved), or "" if none is free.
std::string SameLengthAlias(const std::string& text, const std::string& name,
                            const std::set<std::string>& taken) {
  for (size_t tail = 1; tail <= std::min<size_t>(name.size() - 1, 3); ++tail) {
    for (int n = 0; n < 1000; ++n) {
      std::string digits = std::to_string(n);
      if (digits.size() > tail) break;
      digits.insert(0, tail - digits.size(), '0');
      std::string alias = name.substr(0, name.size() - tail) + digits;
      if (text.find(alias) == std::string::npos && !taken.contains(alias)) return alias;
    }
  }
  return {};
}

// Calls `visit(name, symbol)` for every name that declares or refers to a symbol:
// functions, calls, declarators and identifiers.
template <typename Visit>
void VisitNames(const BrowserContext& context, Visit visit) {
  const glsl::SemanticModel& model = *context.model;
  glsl::VisitPreorder(*context.tree, [&](const glsl::Node& node, uint32_t) {
    if (const auto* function = node.As<glsl::FunctionDeclaration>()) {
      visit(function->name, model.SymbolAt(function->id));
    } else if (const auto* call = node.As<glsl::CallExpr>();
               call != nullptr && call->call_kind == glsl::CallKind::kFunction) {
      visit(call->callee, model.SymbolAt(call->id));
    } else if (const auto* declarator = node.As<glsl::Declarator>()) {
      visit(declarator->name, model.SymbolAt(declarator->id));
    } else if (const auto* identifier = node.As<glsl::IdentifierExpr>()) {
      visit(glsl::Name{identifier->name, identifier->range}, model.SymbolAt(identifier->id));
    }
    return true;
  });
}

bool SpelledIn(const glsl::Name& name, FileId part, const std::string& text) {
  return name.range.file == part && name.range.end <= text.size() &&
         text.compare(name.range.begin, name.text.size(), name.text) == 0;
}

// A local variable named like a struct of an enclosing scope (`struct d1 {...};` and
// `vec2 d0, d1;` in a function): browsers' grammar takes a type name as a declarator's
// name anywhere (ANGLE's `identifier: IDENTIFIER | TYPE_NAME`), glslang only right
// after a type, so `, d1` is its syntax error. In the same scope both call it a
// redefinition.
// `structs`: the scopes of the unit's struct types, by name.
bool HidesStructName(const std::multimap<std::string_view, uint32_t>& structs,
                     const glsl::Symbol& variable) {
  if (variable.kind != glsl::SymbolKind::kVariable || variable.scope == 0) return false;
  const auto [begin, end] = structs.equal_range(variable.name);
  return std::any_of(begin, end, [&](const auto& other) { return other.second != variable.scope; });
}

// Renames, in `text` (the user's file), every function browsers let the shader declare
// under a built-in's name and every call of it, and every variable glslang cannot
// declare under its name, to one alias per name of the same length, so that offsets
// stay put.
void RenameDeclarableBuiltins(const BrowserContext& context, FileId part, std::string& text) {
  if (context.model == nullptr || context.tree == nullptr || context.front_end_errors) return;
  const glsl::SemanticModel& model = *context.model;
  std::set<uint32_t> renamed;
  std::set<uint32_t> hiding_struct;  // renamed only when every name of them is in `text`
  std::multimap<std::string_view, uint32_t> structs;
  for (const glsl::Symbol& symbol : model.symbols) {
    if (symbol.kind == glsl::SymbolKind::kStruct) structs.emplace(symbol.name, symbol.scope);
  }
  for (uint32_t i = 0; i < model.symbols.size(); ++i) {
    const glsl::Symbol& symbol = model.symbols[i];
    if (symbol.predeclared) continue;
    const bool function =
        symbol.kind == glsl::SymbolKind::kFunction && BrowserAcceptsName(context, symbol);
    // GLSL ES 3.00 globals named like a built-in function (`const int max = 4;`) hide it
    // in browsers; glslang calls them a redefinition.
    const bool global = symbol.kind == glsl::SymbolKind::kVariable && symbol.scope == 0 &&
                        ((context.version >= 300 && glsl::IsBuiltinFunctionName(symbol.name)) ||
                         GlslangOnlyFunctionName(context, symbol.name));
    if (function || global) renamed.insert(i);
    if (HidesStructName(structs, symbol)) renamed.insert(i), hiding_struct.insert(i);
  }
  if (!hiding_struct.empty()) {
    VisitNames(context, [&](const glsl::Name& name, uint32_t symbol) {
      if (hiding_struct.contains(symbol) && !SpelledIn(name, part, text)) renamed.erase(symbol);
    });
  }
  // One alias per name (overloads and same-named locals share it).
  std::map<std::string, std::string> aliases;
  std::set<std::string> taken;
  for (const uint32_t symbol : renamed) {
    const std::string& name = model.symbols[symbol].name;
    if (aliases.contains(name)) continue;
    std::string alias = SameLengthAlias(text, name, taken);
    if (!alias.empty()) aliases[name] = alias, taken.insert(alias);
  }
  if (aliases.empty()) return;
  VisitNames(context, [&](const glsl::Name& name, uint32_t symbol) {
    if (!renamed.contains(symbol) || !SpelledIn(name, part, text)) {
      return;  // spelled inside a macro: glslang keeps its complaint
    }
    const auto alias = aliases.find(name.text);
    if (alias != aliases.end()) text.replace(name.range.begin, alias->second.size(), alias->second);
  });
}

// A struct field named `length` (`struct Ray { vec3 o; float length; };`, read as
// `ray.length`): browsers look the field up, glslang reads `.length` as the array
// method and stops ("does not operate on this type"). The field and every read of it
// get one same-length alias in each part, when all of them are spelled in the parts.
void RenameLengthFields(const BrowserContext& context, FileId part, std::string& text) {
  if (context.model == nullptr || context.tree == nullptr || context.front_end_errors ||
      text.find("length") == std::string::npos) {
    return;
  }
  std::vector<glsl::Name> names;
  bool spelled = true;
  const auto add = [&](const glsl::Name& name) {
    const std::string_view in = OriginalText(context, name.range.file);
    spelled =
        spelled && name.range.begin + 6 <= in.size() && in.substr(name.range.begin, 6) == "length";
    names.push_back(name);
  };
  glsl::VisitPreorder(*context.tree, [&](const glsl::Node& node, uint32_t) {
    if (const auto* specifier = node.As<glsl::StructSpecifier>()) {
      for (const glsl::VariableDeclaration* field : specifier->fields) {
        for (const glsl::Declarator* declarator : field->declarators) {
          if (declarator->name.text == "length") add(declarator->name);
        }
      }
    } else if (const auto* member = node.As<glsl::MemberExpr>();
               member != nullptr && member->member.text == "length" && member->object != nullptr &&
               context.model->TypeOf(member->object->id).IsStruct()) {
      add(member->member);
    }
    return true;
  });
  if (names.empty() || !spelled) return;
  const std::string alias = SameLengthAlias(UnitText(context, text), "length");
  if (alias.empty()) return;
  for (const glsl::Name& name : names) {
    if (name.range.file == part && name.range.begin + 6 <= text.size() &&
        text.compare(name.range.begin, 6, "length") == 0) {
      text.replace(name.range.begin, 6, alias);
    }
  }
}

// Words glslang reserves that browsers let a shader use as names (measured in Chromium
// 156 against glslang 12, declaring and reading `float WORD`), by GLSL ES version.
constexpr std::array<std::string_view, 9> kEs1Names = {"active",
                                                       "case",
                                                       "common",
                                                       "filter",
                                                       "isamplerCubeArray",
                                                       "partition",
                                                       "samplerCubeArray",
                                                       "samplerCubeArrayShadow",
                                                       "usamplerCubeArray"};
constexpr std::array<std::string_view, 26> kEs3Names = {"devicecoherent",
                                                        "dmat2",
                                                        "dmat2x2",
                                                        "dmat2x3",
                                                        "dmat2x4",
                                                        "dmat3",
                                                        "dmat3x2",
                                                        "dmat3x3",
                                                        "dmat3x4",
                                                        "dmat4",
                                                        "dmat4x2",
                                                        "dmat4x3",
                                                        "dmat4x4",
                                                        "iimage2DRect",
                                                        "image2DRect",
                                                        "isamplerCubeArray",
                                                        "nonprivate",
                                                        "queuefamilycoherent",
                                                        "samplerCubeArray",
                                                        "samplerCubeArrayShadow",
                                                        "shadercallcoherent",
                                                        "shared",
                                                        "subgroupcoherent",
                                                        "uimage2DRect",
                                                        "usamplerCubeArray",
                                                        "workgroupcoherent"};

// Replaces every whole word `word` of `text` by `with` (of the same length).
void ReplaceWord(std::string& text, std::string_view word, std::string_view with) {
  for (size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
    const bool starts = at == 0 || !directive_text::IsWordChar(text[at - 1]);
    const bool ends =
        at + word.size() >= text.size() || !directive_text::IsWordChar(text[at + word.size()]);
    if (starts && ends) text.replace(at, word.size(), with);
  }
}

// Names glslang reserves and browsers do not: renamed everywhere in the file (comments
// and macro bodies too, which keeps every use consistent) at the same length.
static_assert(std::is_sorted(kEs1Names.begin(), kEs1Names.end()));
static_assert(std::is_sorted(kEs3Names.begin(), kEs3Names.end()));

// [A-Za-z0-9_], as a table: the scan below runs over every byte of every file.
constexpr std::array<bool, 256> kWordChars = [] {
  std::array<bool, 256> table{};
  for (int c = 0; c < 256; ++c) {
    table[static_cast<size_t>(c)] =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
  }
  return table;
}();

void RenameGlslangOnlyKeywords(const BrowserContext& context, FileId part, std::string& text) {
  const std::span<const std::string_view> words =
      context.version >= 300 ? std::span<const std::string_view>(kEs3Names)
                             : std::span<const std::string_view>(kEs1Names);
  std::array<bool, 256> first_chars{};
  for (std::string_view word : words) first_chars[static_cast<unsigned char>(word[0])] = true;
  // Which listed words the code has (most texts: none), from the words of the lexed file
  // or one pass over the text of another part: searching the text once per listed word
  // cost more than the rest of this file. A word only in a comment needs no rename.
  std::vector<bool> present(words.size(), false);
  bool any = false;
  const auto note = [&](std::string_view word) {
    if (word.empty() || !first_chars[static_cast<unsigned char>(word[0])]) return;
    const auto at = std::lower_bound(words.begin(), words.end(), word);
    if (at != words.end() && *at == word) {
      present[static_cast<size_t>(at - words.begin())] = true;
      any = true;
    }
  };
  if (context.lexed != nullptr && context.file != nullptr && context.file->Id() == part) {
    for (const glsl::Token& token : context.lexed->tokens) {
      if (token.kind == glsl::TokenKind::kIdentifier) note(token.text);
    }
  } else {
    const auto is_word = [](char c) { return kWordChars[static_cast<unsigned char>(c)]; };
    for (size_t i = 0; i < text.size();) {
      size_t end = i;
      while (end < text.size() && is_word(text[end])) ++end;
      if (end == i) {
        ++i;
        continue;
      }
      note(std::string_view(text.data() + i, end - i));
      i = end;
    }
  }
  if (!any) return;
  for (size_t k = 0; k < words.size(); ++k) {
    if (!present[k]) continue;
    const std::string alias = SameLengthAlias(text, std::string(words[k]));
    if (!alias.empty()) ReplaceWord(text, words[k], alias);
  }
}

}  // namespace shaderport::rules::glslang_text
