#include "validate/glslang_validator.h"

#include <algorithm>
#include <map>
#include <memory>
#include <optional>

#include "base/limits.h"
#include "glsl/lex/lexer.h"
#include "validate/glslang_rules.h"
#include "validate/line_directives.h"
#include "validate/user_code_scan.h"

namespace shaderport::validate {
namespace {

std::string InternalPartName(size_t index) { return "p" + std::to_string(index); }

// A part's text as a SourceFile plus its tokens: the caller's, or built when first needed.
struct PartView {
  const SourceFile* file = nullptr;
  const glsl::LexedFile* tokens = nullptr;
  std::unique_ptr<SourceFile> owned_file;
  std::unique_ptr<glsl::LexedFile> owned_tokens;

  const glsl::LexedFile& Lexed() const { return *tokens; }
};

class Mapper {
 public:
  explicit Mapper(const ValidationRequest& request)
      : request_(request), views_(request.parts.size()) {
    for (size_t i = 0; i < request.parts.size(); ++i) {
      if (request.parts[i].kind == PartKind::kUser) last_user_ = static_cast<int>(i);
    }
  }

  const PartView& View(int index) {
    std::optional<PartView>& view = views_[static_cast<size_t>(index)];
    if (!view) {
      const ShaderPart& part = request_.parts[static_cast<size_t>(index)];
      view.emplace();
      if (part.source != nullptr && part.lexed != nullptr) {
        view->file = part.source;
        view->tokens = part.lexed;
      } else {
        view->owned_file = std::make_unique<SourceFile>(
            part.file, part.name, std::string(part.text), part.kind == PartKind::kGenerated);
        view->owned_tokens = std::make_unique<glsl::LexedFile>(glsl::Lex(*view->owned_file));
        view->file = view->owned_file.get();
        view->tokens = view->owned_tokens.get();
      }
    }
    return *view;
  }

  int PartIndex(std::string_view name) const {
    for (size_t i = 0; i < request_.parts.size(); ++i) {
      if (InternalPartName(i) == name) return static_cast<int>(i);
    }
    return -1;
  }

  bool UserCodeHasUnbalancedMacro() {
    for (size_t i = 0; i < request_.parts.size(); ++i) {
      if (request_.parts[i].kind != PartKind::kUser) continue;
      if (HasUnbalancedMacroBody(View(static_cast<int>(i)).Lexed())) return true;
    }
    return false;
  }

  bool UserMacroOpensABrace() {
    for (size_t i = 0; i < request_.parts.size(); ++i) {
      if (request_.parts[i].kind != PartKind::kUser) continue;
      if (MacroBodyOpens(View(static_cast<int>(i)).Lexed(), glsl::Punct::kLeftBrace,
                         glsl::Punct::kRightBrace)) {
        return true;
      }
    }
    return false;
  }

  Diagnostic Map(const MappedMessage& mapped) {
    const GlslangMessage& message = mapped.message;
    Diagnostic diagnostic;
    diagnostic.severity = message.severity;
    diagnostic.rule_id = std::string(ClassifyGlslangMessage(message));
    diagnostic.message = TidyGlslangText(message);
    if (mapped.part < 0) {
      // Link errors have no location: they are about the user's code as a whole,
      // or about its entry point (missing, or defined with another signature).
      diagnostic.range = UserFileStart();
      if (MentionsEntryPoint(message)) {
        diagnostic.range = EntryPointInUserCode();
        diagnostic.message = "no definition of " + request_.entry_point_signature +
                             " (glslang: " + diagnostic.message + ")";
      }
      return diagnostic;
    }
    const ShaderPart& part = request_.parts[static_cast<size_t>(mapped.part)];
    const PartView& view = View(mapped.part);
    const SourceRange on_line = LocateOnLine(*view.file, view.Lexed(), message.line, message.token);
    if (part.kind == PartKind::kUser) {
      diagnostic.range = on_line;
      // A syntax error at the very start of a pass may be the end of the Common
      // code compiled before it (a struct without its ';'): say where that is.
      if (diagnostic.rule_id == "glslang/syntax-error") {
        const glsl::Token* first = FirstCodeToken(view.Lexed());
        if (first != nullptr && on_line.begin == first->begin) {
          if (const std::optional<SourceRange> end = UserCodeEndBefore(mapped.part, 1)) {
            diagnostic.notes.push_back(
                {*end,
                 "the code compiled before this file ends here; an unfinished declaration "
                 "there (such as a struct without its ';') is reported at the next token"});
          }
        }
      }
      return diagnostic;
    }
    if (message.severity != Severity::kError) {
      // A warning about generated text is not the user's business, but not hidden either.
      diagnostic.severity = Severity::kNote;
    }
    const std::string_view generated_line =
        view.file->LineText(std::clamp<uint32_t>(message.line, 1, view.file->LineCount()));
    if (const std::optional<UserMacro> macro = MacroOnGeneratedLine(mapped.part, message.line)) {
      return MacroRewritesGeneratedCode(std::move(diagnostic), *macro, generated_line);
    }
    if (MentionsEntryPoint(message)) return EntryPointMismatch(std::move(diagnostic));
    if (UserCodeIsUnfinished()) return IncompleteCode(std::move(diagnostic));
    if (const std::optional<SourceRange> end = UserCodeEndBefore(mapped.part, message.line)) {
      diagnostic.range = *end;
      const std::string_view next = Trimmed(generated_line);
      diagnostic.message += next.empty()
                                ? std::string(" (glslang saw this only after the end of the code)")
                                : " (glslang saw this only at the code that follows, "
                                  "which is not yours: `" +
                                      std::string(next) + "`)";
      return diagnostic;
    }
    diagnostic.rule_id = "internal/generated-code";
    diagnostic.range = part.file == kNoFile ? SourceRange{} : on_line;
    diagnostic.message = "glslang reported an error in shaderport's generated " + part.name +
                         " (line " + std::to_string(message.line) + "): " + diagnostic.message;
    return diagnostic;
  }

 private:
  static std::string_view Trimmed(std::string_view text) {
    const size_t begin = text.find_first_not_of(" \t\r");
    if (begin == std::string_view::npos) return {};
    return text.substr(begin, text.find_last_not_of(" \t\r") - begin + 1);
  }

  // A macro of the user's code that is spelled on `line` of the generated part
  // `index`: the user's code is compiled before it, so the macro rewrites it.
  std::optional<UserMacro> MacroOnGeneratedLine(int index, uint32_t line) {
    std::vector<UserMacro> macros;
    for (int i = 0; i < index; ++i) {
      if (request_.parts[static_cast<size_t>(i)].kind != PartKind::kUser) continue;
      CollectUserMacros(View(i).Lexed(), request_.parts[static_cast<size_t>(i)].file, macros);
    }
    if (macros.empty()) return std::nullopt;
    const PartView& view = View(index);
    line = std::clamp<uint32_t>(line, 1, view.file->LineCount());
    const uint32_t begin = view.file->LineStart(line);
    const uint32_t end = begin + static_cast<uint32_t>(view.file->LineText(line).size());
    for (const glsl::Token& token : view.Lexed().tokens) {
      if (token.begin < begin || token.begin >= end) continue;
      if (token.kind != glsl::TokenKind::kIdentifier) continue;
      for (const UserMacro& macro : macros) {
        if (macro.name == token.text) return macro;
      }
    }
    return std::nullopt;
  }

  Diagnostic MacroRewritesGeneratedCode(Diagnostic diagnostic, const UserMacro& macro,
                                        std::string_view generated_line) {
    diagnostic.rule_id = "shadertoy/macro-rewrites-wrapper";
    diagnostic.severity = Severity::kError;
    diagnostic.range = {macro.file, macro.begin, macro.end};
    diagnostic.message = "the macro '" + std::string(macro.name) +
                         "' rewrites the code the site compiles after yours: `" +
                         std::string(Trimmed(generated_line)) +
                         "` no longer compiles (glslang: " + diagnostic.message + ")";
    return diagnostic;
  }

  // When the error is on the first code line of a generated part that directly
  // follows user code (blank separators aside), the user's last token: glslang
  // reports a missing or extra ';' only when it reads the next token.
  std::optional<SourceRange> UserCodeEndBefore(int index, uint32_t line) {
    const PartView& generated = View(index);
    const uint32_t first_code_line = FirstCodeLine(*generated.file, generated.Lexed());
    if (first_code_line != 0 && line > first_code_line) return std::nullopt;
    for (int i = index - 1; i >= 0; --i) {
      const ShaderPart& part = request_.parts[static_cast<size_t>(i)];
      if (part.kind == PartKind::kUser) {
        const PartView& user = View(i);
        const glsl::Token* last = LastCodeToken(user.Lexed());
        if (last == nullptr) return std::nullopt;
        return SourceRange{part.file, last->begin, last->end};
      }
      const PartView& between = View(i);
      if (FirstCodeLine(*between.file, between.Lexed()) != 0) return std::nullopt;
    }
    return std::nullopt;
  }

  SourceRange UserFileStart() const {
    if (last_user_ < 0) return {};
    return {request_.parts[static_cast<size_t>(last_user_)].file, 0, 0};
  }

  bool MentionsEntryPoint(const GlslangMessage& message) const {
    const std::string& name = request_.entry_point;
    return !name.empty() && (message.token == name || message.text.find(name) != std::string::npos);
  }

  bool UserCodeIsUnfinished() {
    if (!unfinished_) {
      OpenConstructs open;
      for (size_t i = 0; i < request_.parts.size(); ++i) {
        if (request_.parts[i].kind == PartKind::kUser) {
          open += CountOpenConstructs(View(static_cast<int>(i)).Lexed());
        }
      }
      // A macro whose body opens a brace it does not close (a '}' lost from a
      // multi-line #define) leaves the expanded code unclosed though the text is not.
      unfinished_ = open.Any() || UserCodeHasUnbalancedMacro() || UserMacroOpensABrace();
    }
    return *unfinished_;
  }

  // The first definition or declaration of the entry point in user code, else the file.
  SourceRange EntryPointInUserCode() {
    for (int i = last_user_; i >= 0; --i) {
      if (request_.parts[static_cast<size_t>(i)].kind != PartKind::kUser) continue;
      const PartView& view = View(i);
      const auto& tokens = view.Lexed().tokens;
      for (size_t k = 0; k + 1 < tokens.size(); ++k) {
        if (tokens[k].kind == glsl::TokenKind::kIdentifier &&
            tokens[k].text == request_.entry_point &&
            tokens[k + 1].punct == glsl::Punct::kLeftParen) {
          return {view.file->Id(), tokens[k].begin, tokens[k].end};
        }
      }
    }
    return UserFileStart();
  }

  Diagnostic EntryPointMismatch(Diagnostic diagnostic) {
    diagnostic.rule_id = "glslang/entry-point-mismatch";
    diagnostic.range = EntryPointInUserCode();
    diagnostic.message = request_.entry_point + " must be declared as " +
                         request_.entry_point_signature + " (glslang: " + diagnostic.message + ")";
    return diagnostic;
  }

  Diagnostic IncompleteCode(Diagnostic diagnostic) {
    diagnostic.rule_id = "glslang/incomplete-code";
    SourceRange end = UserFileStart();
    if (last_user_ >= 0) {
      const auto size =
          static_cast<uint32_t>(request_.parts[static_cast<size_t>(last_user_)].text.size());
      end.begin = end.end = size;
    }
    diagnostic.range = end;
    diagnostic.message =
        "the code ends inside an unclosed brace, parenthesis or #if, so glslang reports an error "
        "in the code that follows it (glslang: " +
        diagnostic.message + ")";
    return diagnostic;
  }

  const ValidationRequest& request_;
  std::vector<std::optional<PartView>> views_;
  int last_user_ = -1;
  std::optional<bool> unfinished_;
};

void AppendMessages(std::string_view log, const Mapper& mapper, std::vector<MappedMessage>& out) {
  for (GlslangMessage& message : ParseGlslangLog(log)) {
    MappedMessage mapped;
    mapped.part = message.part.empty() ? -1 : mapper.PartIndex(message.part);
    mapped.message = std::move(message);
    out.push_back(std::move(mapped));
  }
}

// Errors in generated code after unfinished user code are all one problem: keep
// the first as the diagnostic and the rest as its notes.
void AddDiagnostic(Diagnostic diagnostic, DiagnosticList& out) {
  if (diagnostic.rule_id == "glslang/incomplete-code") {
    for (Diagnostic& previous : out) {
      if (previous.rule_id == diagnostic.rule_id) {
        previous.notes.push_back({SourceRange{}, diagnostic.message});
        return;
      }
    }
  }
  if (out.size() >= limits::kMaxDiagnosticsPerFile) {
    if (out.back().notes.empty() ||
        out.back().notes.back().message != "further glslang messages were dropped") {
      out.back().notes.push_back({SourceRange{}, "further glslang messages were dropped"});
    }
    return;
  }
  out.push_back(std::move(diagnostic));
}

}  // namespace

ValidationResult ValidateWithGlslang(const ValidationRequest& request) {
  ValidationResult result;
  Mapper mapper(request);
  std::vector<GlslangPart> parts;
  std::vector<std::string> renumbered(request.parts.size());  // user parts without #line
  for (size_t i = 0; i < request.parts.size(); ++i) {
    std::string_view text = request.parts[i].text;
    if (request.parts[i].kind == PartKind::kUser) renumbered[i] = WithoutLineDirectives(text);
    if (!renumbered[i].empty()) text = renumbered[i];
    parts.push_back({InternalPartName(i), text});
  }
  const GlslangRun run =
      mapper.UserCodeHasUnbalancedMacro() && !request.texts_expanded
          ? RunGlslangIsolated(parts, request.stage, request.default_version, request.link)
          : RunGlslang(parts, request.stage, request.default_version, request.link);
  result.crashed = run.crashed || !run.ran;
  result.compiled = run.compiled;
  result.linked = run.linked;
  if (result.crashed) {
    Diagnostic diagnostic;
    diagnostic.rule_id = run.crashed ? "glslang/crashed" : "internal/error";
    diagnostic.message = run.crashed ? "glslang crashed or hung on this input; it was not validated"
                                     : "glslang could not be started (no thread)";
    for (auto it = request.parts.rbegin(); it != request.parts.rend(); ++it) {
      if (it->kind == PartKind::kUser) {
        diagnostic.range = {it->file, 0, 0};
        break;
      }
    }
    result.diagnostics.push_back(std::move(diagnostic));
    return result;
  }
  AppendMessages(run.compile_log, mapper, result.messages);
  AppendMessages(run.link_log, mapper, result.messages);
  for (const MappedMessage& mapped : result.messages) {
    AddDiagnostic(mapper.Map(mapped), result.diagnostics);
  }
  return result;
}

}  // namespace shaderport::validate
