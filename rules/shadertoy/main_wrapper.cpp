// shadertoy/main-wrapper: the harness's entry point (ShaderToy's mainImage,
// mainCubemap, mainSound, or a dialect file's) gets the real main() the host
// would generate, appended at the end of the file; the output is a declared
// `out highp vec4`. The Image pass's alpha is forced to 1 as on the site; a
// Buffer pass keeps it (the dialect's buffer_main).
//
// Before:                                   After:
//   void mainImage(out vec4 c, in vec2 p) {   void mainImage(out vec4 c, in vec2 p) {
//     c = vec4(p / iResolution.xy, 0, 1);       c = vec4(p / iResolution.xy, 0, 1);
//   }                                         }
//                                             out highp vec4 fragColor;
//                                             void main() {
//                                               vec4 color = vec4(1e20);
//                                               mainImage(color, gl_FragCoord.xy);
//                                               fragColor = vec4(color.xyz, 1.0);
//                                             }
//
// Harnesses where the user writes main() (glslsandbox, the raymarch blog) have no
// entry points: nothing to do here (shadertoy/uniforms declares their output).
#include <map>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/shadertoy/harness_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "shadertoy/main-wrapper";

// Replaces {entry}, {out} and {fresh:NAME} in a main() template.
std::string ExpandTemplate(std::string_view body, std::string_view entry, std::string_view out,
                           harness::FreshNames& fresh) {
  std::map<std::string, std::string, std::less<>> locals;
  std::string text;
  size_t i = 0;
  while (i < body.size()) {
    const size_t close = body[i] == '{' ? body.find('}', i) : std::string_view::npos;
    const std::string_view inside =
        close == std::string_view::npos ? std::string_view() : body.substr(i + 1, close - i - 1);
    if (inside == "entry") {
      text += entry;
    } else if (inside == "out") {
      text += out;
    } else if (inside.starts_with("fresh:")) {
      const std::string_view base = inside.substr(6);
      auto it = locals.find(base);
      if (it == locals.end()) it = locals.emplace(std::string(base), fresh.Make(base)).first;
      text += it->second;
    } else {
      text += body[i++];
      continue;
    }
    i = close + 1;
  }
  return text;
}

// Indents each non-empty line of `body` by two spaces.
std::string Indent(std::string_view body) {
  std::string text;
  size_t start = 0;
  while (start < body.size()) {
    size_t end = body.find('\n', start);
    if (end == std::string_view::npos) end = body.size();
    const std::string_view line = body.substr(start, end - start);
    if (!line.empty()) text += "  " + std::string(line) + "\n";
    start = end + 1;
  }
  return text;
}

// False when text appended at the end would be swallowed by an unterminated
// block comment or a line continuation.
bool EndIsOpen(const rule::RuleContext& context) {
  const std::string_view text = context.Text();
  if (text.ends_with("\\") || text.ends_with("\\\n") || text.ends_with("\\\r\n")) return false;
  const auto& lexed = context.Lexed();
  if (lexed.tokens.empty()) return true;
  const glsl::Token& end = lexed.tokens.back();
  for (uint32_t i = end.trivia_begin; i < end.trivia_end && i < lexed.trivia.size(); ++i) {
    const glsl::Trivia& trivia = lexed.trivia[i];
    const std::string_view comment = text.substr(trivia.begin, trivia.end - trivia.begin);
    if (trivia.kind == glsl::TriviaKind::kBlockComment &&
        (comment.size() < 4 || !comment.ends_with("*/"))) {
      return false;
    }
  }
  return true;
}

// The entry point defined as a function-like macro in this file, and where its
// name is; nullptr when there is none.
const model::EntryPoint* MacroEntryPoint(const rule::RuleContext& context,
                                         const model::HarnessDialect& dialect, SourceRange& where) {
  const auto& tokens = context.Lexed().tokens;
  for (size_t i = 0; i + 3 < tokens.size(); ++i) {
    if (tokens[i].kind != glsl::TokenKind::kHash || tokens[i + 1].text != "define" ||
        tokens[i + 2].at_line_start || tokens[i + 3].text != "(" ||
        tokens[i + 3].begin != tokens[i + 2].end) {  // function-like: "(" right after the name
      continue;
    }
    for (const model::EntryPoint& entry : dialect.entry_points) {
      if (tokens[i + 2].text == entry.function) {
        where = {context.File().Id(), tokens[i + 2].begin, tokens[i + 2].end};
        return &entry;
      }
    }
  }
  return nullptr;
}

// A function defined inside another one: the parser's recovery from an error (an invalid
// byte, a '}' missing) ran to the end of the file. A main() added there was found
// nested, never at top level, and was added again every round.
bool NestedFunctionDefinition(const glsl::SyntaxTree& tree) {
  bool nested = false;
  glsl::VisitPreorder(tree, [&](const glsl::Node& node, uint32_t depth) {
    const auto* function = node.As<glsl::FunctionDeclaration>();
    if (function != nullptr && function->body != nullptr && depth > 1) nested = true;
    return !nested;
  });
  return nested;
}

// `void main (` in the compiled tokens (inactive #if groups left out, macros expanded).
// Where the parser's recovery from an error put a main() added by an earlier round out
// of the tree's reach (after a stray '}'), the tokens still show it; without this check
// it was added every round.
bool MainInTokens(const rule::RuleContext& context) {
  const auto& tokens = context.Preprocessed().tokens;
  for (size_t i = 0; i + 2 < tokens.size(); ++i) {
    if (tokens[i].text == "void" && tokens[i + 1].text == "main" &&
        tokens[i + 2].punct == glsl::Punct::kLeftParen) {
      return true;
    }
  }
  return false;
}

class MainWrapperRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{
        kId, "Give a harness entry point such as mainImage the main() its host generates",
        "void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }",
        "void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }\n"
        "out highp vec4 fragColor;\n"
        "void main() {\n  vec4 color = vec4(1e20);\n  mainImage(color, gl_FragCoord.xy);\n"
        "  fragColor = vec4(color.xyz, 1.0);\n}",
        rule::RuleScope::kPort};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    const model::HarnessDialect* dialect = context.Settings().harness;
    if (dialect == nullptr || dialect->entry_points.empty()) return;
    if (context.Settings().stage != model::Stage::kFragment) return;
    const rule::CodeInterface code = rule::ReadCodeInterface(context.Tree(), context.Model());
    if (code.defined_functions.contains("main")) return;  // already has one (or ported)
    if (NestedFunctionDefinition(context.Tree()) || MainInTokens(context)) return;
    // An #if left open (or another preprocessor error) may hide what is added in a
    // group that is not compiled: it would be added again every round.
    if (HasErrors(context.Preprocessed().diagnostics)) return;
    const model::EntryPoint* entry = harness::DefinedEntryPoint(*dialect, code);
    SourceRange where;
    if (entry != nullptr) {
      const glsl::FunctionDeclaration* definition =
          harness::FindDefinition(context, entry->function);
      if (definition == nullptr || definition->name.range.file != context.File().Id()) return;
      where = definition->name.range;
    } else {
      // `#define mainImage(c, p) (c = Main(p))`: the site's main() reaches the user's
      // code through the macro, and so does the generated one.
      entry = MacroEntryPoint(context, *dialect, where);
      if (entry == nullptr) return;
    }

    harness::FreshNames fresh(context);
    const std::string out = fresh.Make(entry->output_name);
    const std::string& main_body =
        context.Settings().buffer_pass && !entry->buffer_main_body.empty() ? entry->buffer_main_body
                                                                           : entry->main_body;
    const std::string body = ExpandTemplate(main_body, entry->function, out, fresh);
    const std::string_view text = context.Text();
    std::string insertion = text.empty() || text.back() == '\n' ? "\n" : "\n\n";
    // `#define main() mainImage(...)` would rewrite the added main() too (and every
    // round would add another): the user's macro has done its work by the end.
    const bool main_is_macro = harness::DefinedMacros(context).contains("main");
    if (main_is_macro) insertion += "#undef main\n";
    insertion += "out highp vec4 " + out + ";\nvoid main() {\n" + Indent(body) + "}\n";

    Diagnostic diagnostic;
    diagnostic.severity = Severity::kWarning;
    diagnostic.rule_id = std::string(kId);
    diagnostic.range = where;
    diagnostic.message = "WebGL2 needs a main(); " + dialect->name + " calls " + entry->function +
                         "() from one it generates: adding it, with output '" + out + "'" +
                         (main_is_macro ? " ('main' is a macro here: #undef'd first)" : "");
    const auto end = static_cast<uint32_t>(text.size());
    if (EndIsOpen(context)) {
      diagnostic.fixes.push_back(
          FixIt{{context.File().Id(), end, end}, std::move(insertion), FixSafety::kSafe});
    } else {
      diagnostic.notes.push_back({{context.File().Id(), end, end},
                                  "not fixed automatically: the file ends inside a comment or "
                                  "a line continuation"});
    }
    context.Report(std::move(diagnostic));
  }
};

}  // namespace

const rule::Rule& ShadertoyMainWrapperRule() {
  static const MainWrapperRule rule;
  return rule;
}

}  // namespace shaderport::rules
