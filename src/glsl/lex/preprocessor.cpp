#include "glsl/lex/preprocessor.h"

#include <algorithm>
#include <cstring>

#include "base/large_stack.h"
#include "base/limits.h"
#include "diag/limit_breach.h"
#include "glsl/lex/macro_definitions.h"
#include "glsl/lex/macro_expander.h"
#include "glsl/lex/pp_driver.h"

namespace shaderport::glsl {

PpDriver::PpDriver(PreprocessResult& result, const PreprocessOptions& options)
    : state_(result), max_identifier_length_(options.max_identifier_length) {
  AddPredefinedMacros(state_, options.predefined);
}

void PpDriver::RunFile(const SourceFile& file, size_t index, const LexedFile* given,
                       int64_t first_line) {
  file_ = &file;
  file_index_ = index;
  state_.file = &file;
  state_.line_delta = first_line > 0 ? first_line - 1 : 0;
  state_.source_number = first_line > 0 ? 0 : static_cast<int>(index);
  const size_t first_region = state_.result.inactive_regions.size();
  const size_t outer_groups = groups_.size();
  LexedFile own;
  if (given == nullptr) own = Lex(file);
  const LexedFile& lexed = given != nullptr ? *given : own;
  const std::vector<Token>& tokens = lexed.tokens;
  const std::string_view text = file.Text();
  file_has_backslash_ = !text.empty() && std::memchr(text.data(), '\\', text.size()) != nullptr;
  size_t i = 0;
  while (tokens[i].kind != TokenKind::kEndOfFile) {
    size_t end = i + 1;
    if (tokens[i].kind != TokenKind::kHash) {
      // A run of text up to the next directive: only a directive can change whether
      // code is active, so the whole run is compiled or skipped.
      while (tokens[end].kind != TokenKind::kEndOfFile && tokens[end].kind != TokenKind::kHash) {
        ++end;
      }
      if (Active()) {
        for (size_t k = i; k < end; ++k) CheckIdentifierLength(tokens[k]);
        FlushText(std::span<const Token>(tokens).subspan(i, end - i));
      }
      seen_token_ = true;
      i = end;
      continue;
    }
    while (tokens[end].kind != TokenKind::kEndOfFile && !tokens[end].at_line_start) ++end;
    Directive(std::span<const Token>(tokens).subspan(i, end - i));
    seen_token_ = true;
    i = end;
  }
  FlushPending();  // a macro call may not span files
  // A conditional group may not span files.
  while (groups_.size() > outer_groups) {
    const ConditionalGroup& g = groups_.back();
    state_.Report(Severity::kError, "preprocessor/unterminated-conditional", g.directive,
                  "this conditional has no #endif");
    // Only the group that started the skipping ends a skipped region here: a taken group
    // skipped nothing, and skip_begin_ may still hold another group's (or file's) start.
    const bool was_active = Active();
    groups_.pop_back();
    if (!was_active && Active()) {
      state_.result.inactive_regions.push_back(
          {file.Id(), skip_begin_, static_cast<uint32_t>(file.Text().size())});
    }
  }
  AddLexDiagnostics(lexed, first_region);
}

void PpDriver::ReportLongIdentifier(const Token& t) {
  // WebGL limits identifiers to 256 characters, and to 1024 in GLSL ES 3.00 (WebGL 2).
  const size_t limit = max_identifier_length_                ? max_identifier_length_
                       : state_.result.version.number >= 300 ? 1024
                                                             : 256;
  // Browsers apply the same limit to every token ("token too long"): numbers too.
  if (t.text.size() <= limit) return;
  const bool identifier = t.kind == TokenKind::kIdentifier;
  state_.Report(
      Severity::kError,
      identifier ? "preprocessor/identifier-too-long" : "preprocessor/token-too-long", RangeOf(t),
      std::string(identifier ? "identifier" : "number") + " of " + std::to_string(t.text.size()) +
          " characters; the limit is " + std::to_string(limit));
}

std::vector<ExpToken> PpDriver::ToExpTokens(std::span<const Token> tokens) {
  std::vector<ExpToken> out;
  out.reserve(tokens.size());
  for (const Token& t : tokens) out.push_back({ToPpToken(*file_, t, state_), false});
  return out;
}

namespace {

// Room for `more` tokens at the end of `out`, growing geometrically: reserving the exact
// size for each run of text copied every token made so far once per run.
void ReserveMore(std::vector<PpToken>& out, size_t more) {
  const size_t need = out.size() + more;
  if (need > out.capacity()) out.reserve(std::max(need, 2 * out.capacity()));
}

}  // namespace

void PpDriver::FlushText(std::span<const Token> text) {
  if (text.empty()) return;
  seen_code_ = true;
  if (pending_.empty() && !EndsInsideMacroCall(text)) {
    auto& out = state_.result.tokens;
    ReserveMore(out, text.size());
    ExpandMacrosInto(state_, *file_, text, file_has_backslash_, out);
    return;
  }
  pending_.insert(pending_.end(), text.begin(), text.end());
  if (!EndsInsideMacroCall(pending_)) FlushPending();
}

void PpDriver::FlushPending() {
  if (pending_.empty()) return;
  auto& out = state_.result.tokens;
  ReserveMore(out, pending_.size());
  ExpandMacrosInto(state_, *file_, pending_, file_has_backslash_, out);
  pending_.clear();
}

bool PpDriver::EndsInsideMacroCall(std::span<const Token> text) const {
  // Cheap first: an open call leaves more '(' than ')'.
  int balance = 0;
  for (const Token& t : text) {
    balance += t.punct == Punct::kLeftParen ? 1 : t.punct == Punct::kRightParen ? -1 : 0;
  }
  if (balance <= 0) return false;
  int depth = 0;
  bool in_call = false;
  for (size_t k = 0; k < text.size(); ++k) {
    const Token& t = text[k];
    if (in_call) {
      depth += t.punct == Punct::kLeftParen ? 1 : t.punct == Punct::kRightParen ? -1 : 0;
      in_call = depth > 0;
      continue;
    }
    if (t.kind != TokenKind::kIdentifier || k + 1 >= text.size() ||
        text[k + 1].punct != Punct::kLeftParen) {
      continue;
    }
    const Macro* macro = state_.Find(t.text);
    if (macro != nullptr && macro->function_like) {
      in_call = true;
      depth = 0;
    }
  }
  return in_call;
}

void PpDriver::AddLexDiagnostics(const LexedFile& lexed, size_t first_region) {
  const auto& regions = state_.result.inactive_regions;
  for (const Diagnostic& d : lexed.diagnostics) {
    // Skipped groups may hold any text (as in C): only comments must still be closed there.
    const bool skipped =
        std::any_of(regions.begin() + static_cast<std::ptrdiff_t>(first_region), regions.end(),
                    [&](const SourceRange& r) { return r.Contains(d.range); });
    if (skipped && d.rule_id == "lex/invalid-character") continue;
    state_.Report(d.severity, d.rule_id, d.range, d.message);
  }
}

void PpDriver::Finish(const SourceFile* last_file) {
  ReportOutputTooLarge();
  PpToken eof;
  if (last_file) {
    const auto size = static_cast<uint32_t>(last_file->Text().size());
    eof.spelling = eof.expansion = {last_file->Id(), size, size};
    eof.text = last_file->Text().substr(size);
  }
  eof.at_line_start = true;
  state_.result.tokens.push_back(eof);
  std::stable_sort(state_.result.diagnostics.begin(), state_.result.diagnostics.end(),
                   [](const Diagnostic& a, const Diagnostic& b) {
                     return a.range.file != b.range.file ? a.range.file < b.range.file
                                                         : a.range.begin < b.range.begin;
                   });
}

void PpDriver::ReportOutputTooLarge() {
  const std::vector<PpToken>& tokens = state_.result.tokens;
  // One breach is enough: the lexer's or the expander's own limit already says why.
  if (tokens.size() <= limits::kMaxCompiledTokens || HasLimitBreach(state_.result.diagnostics)) {
    return;
  }
  state_.Report(Severity::kError, "preprocessor/output-too-large",
                tokens[limits::kMaxCompiledTokens].expansion,
                "the preprocessed shader has " + std::to_string(tokens.size()) +
                    " tokens; glslang is given at most " +
                    std::to_string(limits::kMaxCompiledTokens));
}

PreprocessResult Preprocess(std::span<const SourceFile* const> files,
                            const PreprocessOptions& options) {
  PreprocessResult result;
  // `#if` expressions nest as deep as browsers allow (9,996 parentheses), past what a
  // default thread stack holds: run on a large stack (in place when already on one).
  const auto preprocess = [&] {
    PpDriver driver(result, options);
    for (size_t i = 0; i < files.size(); ++i) {
      driver.RunFile(*files[i], i, i < options.lexed.size() ? options.lexed[i] : nullptr,
                     i < options.first_lines.size() ? options.first_lines[i] : 0);
    }
    driver.Finish(files.empty() ? nullptr : files.back());
  };
  if (!RunOnLongLivedLargeStack(preprocess)) preprocess();
  return result;
}

}  // namespace shaderport::glsl
