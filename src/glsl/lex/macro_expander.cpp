#include "glsl/lex/macro_expander.h"

#include <optional>
#include <span>
#include <string>
#include <utility>

#include "base/limits.h"

namespace shaderport::glsl {
namespace {

// Tokens still to be read: the input at the bottom, one macro's expansion per level above.
struct Context {
  std::vector<ExpToken> tokens;
  size_t next = 0;
  Macro* macro = nullptr;  // disabled until this context is popped
};

// A piece of a substituted body before `##` is applied.
struct Piece {
  ExpToken token;
  bool paste_operator = false;
  bool placemarker = false;  // an empty argument next to ##
};

class Expander {
 public:
  Expander(PpState& state, bool in_if, uint32_t depth)
      : state_(state), in_if_(in_if), depth_(depth) {}

  std::vector<ExpToken> Run(std::vector<ExpToken> input) {
    Drain(std::move(input));
    return std::move(out_);
  }

  // Expands lexed tokens of `file`, each converted when first read, into `out`.
  void RunInto(const SourceFile& file, std::span<const Token> source, bool file_has_backslash,
               std::vector<PpToken>& out) {
    direct_ = &out;
    source_file_ = &file;
    source_ = source;
    source_has_backslash_ = file_has_backslash;
    source_levels_ = 1;  // the source counts as the level a list of input tokens would be
    StepThroughInput();
  }

 private:
  void Drain(std::vector<ExpToken> input) {
    stack_.push_back({std::move(input), 0, nullptr});
    StepThroughInput();
  }

  void StepThroughInput() {
    ExpToken t;
    while (true) {
      if (direct_ != nullptr && stack_.empty() && !source_peeked_) CopyPlainSourceTokens();
      if (!Next(&t)) return;
      Step(t);
    }
  }

  // With no expansion open, the source's tokens up to the next name of a defined macro
  // go to the output as they are (what Step would do): converted in place there, as
  // building each one aside and copying it twice cost more than the conversion. Most
  // runs of code use no macro, or only late. A macro name is converted again when Step
  // reads it, which only stores its spelling twice when it holds a line continuation.
  void CopyPlainSourceTokens() {
    while (source_next_ < source_.size()) {
      const Token& token = source_[source_next_];
      PpToken& converted = direct_->emplace_back();
      ConvertToPpToken(converted, *source_file_, token, state_, source_has_backslash_);
      if (token.kind == TokenKind::kIdentifier && !state_.expansion_exhausted &&
          state_.Find(converted.text) != nullptr) {
        direct_->pop_back();  // Step expands it
        return;
      }
      ++source_next_;
    }
  }

  // Open levels of input: macro expansions, and the input below them.
  size_t Levels() const { return stack_.size() + source_levels_; }

  // The next token of the lazily converted source, if any is left.
  bool NextFromSource(ExpToken* t) {
    if (source_peeked_) {
      *t = *source_peeked_;
      source_peeked_.reset();
      return true;
    }
    if (source_next_ == source_.size()) return false;
    *t = ConvertNextSourceToken();
    return true;
  }

  const ExpToken* PeekSource() {
    if (!source_peeked_ && source_next_ < source_.size()) source_peeked_ = ConvertNextSourceToken();
    return source_peeked_ ? &*source_peeked_ : nullptr;
  }

  ExpToken ConvertNextSourceToken() {
    return {ToPpToken(*source_file_, source_[source_next_++], state_, source_has_backslash_),
            false};
  }

  // A finished token: into the caller's token list when given one (nothing reads the
  // output back while expanding), else into the result.
  void Emit(const ExpToken& t) {
    if (direct_ != nullptr) {
      direct_->push_back(t.token);
    } else {
      out_.push_back(t);
    }
  }

  bool Next(ExpToken* t) {
    while (!stack_.empty()) {
      Context& c = stack_.back();
      if (c.next < c.tokens.size()) {
        *t = c.tokens[c.next++];
        return true;
      }
      if (c.macro) --c.macro->disabled;
      stack_.pop_back();
    }
    return NextFromSource(t);
  }

  // The next token without reading it; looks through finished contexts.
  const ExpToken* Peek() {
    for (auto it = stack_.rbegin(); it != stack_.rend(); ++it) {
      if (it->next < it->tokens.size()) return &it->tokens[it->next];
    }
    return PeekSource();
  }

  void Step(ExpToken t) {
    if (t.token.kind != TokenKind::kIdentifier || t.no_expand || state_.expansion_exhausted) {
      Emit(t);
      return;
    }
    if (in_if_ && t.token.text == "defined") {
      Defined(t);
      return;
    }
    Macro* macro = state_.FindMutable(t.token.text);
    if (!macro) {
      Emit(t);
      return;
    }
    if (macro->disabled > 0) {
      t.no_expand = true;  // a macro never expands inside its own expansion
      Emit(t);
      return;
    }
    if (depth_ + Levels() > limits::kMaxMacroDepth) {
      if (!state_.reported_macro_depth) {
        state_.reported_macro_depth = true;
        state_.Report(Severity::kError, "preprocessor/macro-too-deep", t.token.expansion,
                      "macro expansion nested more than " + std::to_string(limits::kMaxMacroDepth) +
                          " levels deep");
      }
      Emit(t);
      return;
    }
    if (!macro->function_like) {
      Substitute(t, *macro, {}, std::nullopt);
      return;
    }
    const ExpToken* after = Peek();
    if (!after || after->token.punct != Punct::kLeftParen) {
      Emit(t);  // a function-like macro name without '(' is a plain name
      return;
    }
    Call(t, *macro);
  }

  // `defined X` or `defined ( X )` inside #if.
  void Defined(const ExpToken& op) {
    ExpToken value = op;
    value.token.kind = TokenKind::kIntLiteral;
    const ExpToken* p = Peek();
    bool ok = false;
    bool defined = false;
    if (p && p->token.kind == TokenKind::kIdentifier) {
      ExpToken name;
      Next(&name);
      defined = state_.Find(name.token.text) != nullptr;
      ok = true;
    } else if (p && p->token.punct == Punct::kLeftParen) {
      ExpToken paren, name, close;
      Next(&paren);
      if (Next(&name) && name.token.kind == TokenKind::kIdentifier && Next(&close) &&
          close.token.punct == Punct::kRightParen) {
        defined = state_.Find(name.token.text) != nullptr;
        ok = true;
      }
    }
    if (!ok) {
      state_.Report(Severity::kError, "preprocessor/invalid-defined", op.token.expansion,
                    "'defined' must be followed by a macro name or '(' name ')'");
    }
    value.token.text = defined ? "1" : "0";
    Emit(value);
  }

  void Call(ExpToken name, Macro& macro) {
    ExpToken open;
    Next(&open);
    std::vector<std::vector<ExpToken>> args(1);
    std::vector<ExpToken> separators;
    int nesting = 1;
    ExpToken t;
    while (true) {
      if (state_.expanded_tokens > limits::kMaxExpandedTokens) {
        ReportTooLarge(Cover(name.token.expansion, open.token.expansion));
      }
      if (!Next(&t)) {
        state_.Report(Severity::kError, "preprocessor/unterminated-macro-call",
                      Cover(name.token.expansion, open.token.expansion),
                      "the arguments of macro '" + macro.name + "' have no closing ')'");
        Emit(name);
        Emit(open);
        for (size_t i = 0; i < args.size(); ++i) {
          if (i > 0) Emit(separators[i - 1]);
          for (auto& a : args[i]) Emit(a);
        }
        return;
      }
      if (t.token.punct == Punct::kLeftParen) ++nesting;
      if (t.token.punct == Punct::kRightParen && --nesting == 0) break;
      if (t.token.punct == Punct::kComma && nesting == 1) {
        separators.push_back(t);
        args.emplace_back();
        continue;
      }
      state_.expanded_tokens++;  // collecting arguments copies tokens: count them too
      args.back().push_back(t);
    }
    // `F()` passes no argument to a macro without parameters, and one empty argument
    // to a macro with one parameter (real ShaderToy code writes `D( )`).
    if (macro.params.empty() && args.size() == 1 && args[0].empty()) args.clear();
    if (args.size() != macro.params.size()) {
      state_.Report(Severity::kError, "preprocessor/macro-argument-count",
                    Cover(name.token.expansion, t.token.expansion),
                    "macro '" + macro.name + "' takes " + std::to_string(macro.params.size()) +
                        " argument(s) but " + std::to_string(args.size()) + " were given");
      Emit(name);
      return;
    }
    Substitute(name, macro, std::move(args), t);
  }

  void Substitute(const ExpToken& name, Macro& macro, std::vector<std::vector<ExpToken>> args,
                  std::optional<ExpToken> close) {
    const auto use_id = static_cast<uint32_t>(state_.result.macro_uses.size());
    const SourceRange expansion =
        close ? Cover(name.token.expansion, close->token.expansion) : name.token.expansion;
    MacroUse use;
    use.name = macro.name;
    use.use = close ? Cover(name.token.spelling, close->token.spelling) : name.token.spelling;
    use.definition = macro.definition;
    // A name met while pre-expanding an argument belongs to the call it is an argument of.
    use.parent = name.token.macro_use != kNoMacroUse ? name.token.macro_use : argument_of_use_;
    state_.result.macro_uses.push_back(std::move(use));

    std::vector<Piece> pieces;
    if (macro.builtin != BuiltinMacro::kNone) {
      pieces.push_back({BuiltinValue(name, macro.builtin), false, false});
    }
    std::vector<std::optional<std::vector<ExpToken>>> expanded_args(args.size());
    for (size_t i = 0; i < macro.body.size(); ++i) {
      const int param = macro.body_param[i];
      if (param < 0) {
        ExpToken body{macro.body[i], false};
        if (!body.token.spelling.Valid()) body.token.spelling = name.token.spelling;
        body.token.in_macro_body = true;
        const bool paste = body.token.punct == Punct::kHashHash;
        pieces.push_back({body, paste, false});
        continue;
      }
      const bool next_to_paste =
          (i > 0 && macro.body[i - 1].punct == Punct::kHashHash && macro.body_param[i - 1] < 0) ||
          (i + 1 < macro.body.size() && macro.body[i + 1].punct == Punct::kHashHash &&
           macro.body_param[i + 1] < 0);
      const std::vector<ExpToken>* arg = &args[param];
      if (!next_to_paste) {
        auto& cached = expanded_args[param];
        if (!cached) cached = ExpandArgument(args[param], use_id);
        arg = &*cached;
      }
      if (arg->empty() && next_to_paste) pieces.push_back({{}, false, true});
      for (size_t k = 0; k < arg->size(); ++k) {
        ExpToken a = (*arg)[k];
        if (k == 0) a.token.leading_space = macro.body[i].leading_space;
        pieces.push_back({a, false, false});
      }
    }
    std::vector<ExpToken> produced = ApplyPastes(pieces, expansion);
    for (ExpToken& p : produced) {
      p.token.expansion = expansion;
      // Argument tokens that an earlier macro made keep that macro's use (the innermost
      // one that produced them); body tokens and arguments written in the file get this use.
      if (p.token.macro_use == kNoMacroUse) p.token.macro_use = use_id;
    }
    if (!produced.empty()) {
      produced[0].token.leading_space = name.token.leading_space;
      produced[0].token.at_line_start = name.token.at_line_start;
    }
    state_.expanded_tokens += produced.size() + 1;
    if (state_.expanded_tokens > limits::kMaxExpandedTokens || state_.expansion_exhausted) {
      ReportTooLarge(expansion);
      Emit(name);
      return;
    }
    ++macro.disabled;
    stack_.push_back({std::move(produced), 0, &macro});
  }

  void ReportTooLarge(SourceRange at) {
    if (state_.expansion_exhausted) return;
    state_.expansion_exhausted = true;
    state_.Report(Severity::kError, "preprocessor/expansion-too-large", at,
                  "macro expansion produced more than " +
                      std::to_string(limits::kMaxExpandedTokens) +
                      " tokens; no further macros are expanded");
  }

  std::vector<ExpToken> ExpandArgument(const std::vector<ExpToken>& arg, uint32_t use_id) {
    // Each nested pre-expansion holds a copy of its argument: cap the nesting (real code
    // nests a few calls deep) and charge the copy, so memory stays bounded. Arguments past
    // the cap are substituted as written and expanded when the body is rescanned.
    if (arg_nesting_ >= kMaxArgumentNesting || depth_ + Levels() + 1 > limits::kMaxMacroDepth) {
      return arg;
    }
    state_.expanded_tokens += arg.size();
    Expander nested(state_, in_if_, depth_ + static_cast<uint32_t>(Levels()) + 1);
    nested.arg_nesting_ = arg_nesting_ + 1;
    nested.argument_of_use_ = use_id;
    return nested.Run(arg);
  }

  std::vector<ExpToken> ApplyPastes(const std::vector<Piece>& pieces, SourceRange expansion) {
    std::vector<Piece> joined;
    bool pending = false;
    for (const Piece& piece : pieces) {
      if (piece.paste_operator) {
        pending = !joined.empty();
        continue;
      }
      if (!pending) {
        joined.push_back(piece);
        continue;
      }
      pending = false;
      Piece& left = joined.back();
      if (piece.placemarker) continue;
      if (left.placemarker) {
        left = piece;
        continue;
      }
      PpToken pasted;
      if (PasteTokens(state_, left.token.token, piece.token.token, &pasted)) {
        left.token = {pasted, false};
      } else {
        state_.Report(Severity::kError, "preprocessor/invalid-token-paste", expansion,
                      "pasting '" + std::string(left.token.token.text) + "' and '" +
                          std::string(piece.token.token.text) + "' does not give a valid token");
        joined.push_back(piece);
      }
    }
    std::vector<ExpToken> out;
    out.reserve(joined.size());
    for (Piece& p : joined) {
      if (!p.placemarker) out.push_back(p.token);
    }
    return out;
  }

  ExpToken BuiltinValue(const ExpToken& name, BuiltinMacro builtin) {
    ExpToken v = name;
    v.token.kind = TokenKind::kIntLiteral;
    v.token.punct = Punct::kNone;
    v.token.in_macro_body = true;
    int64_t value = 0;
    if (builtin == BuiltinMacro::kLine) {
      const SourceRange at = name.token.expansion;
      const bool here = state_.file && at.file == state_.file->Id();
      value = here ? state_.file->LocationOf(at.begin).line + state_.line_delta : 0;
    } else if (builtin == BuiltinMacro::kFile) {
      value = state_.source_number;
    } else {
      value = state_.result.version.number;
    }
    v.token.text = state_.Store(std::to_string(value));
    return v;
  }

  static constexpr uint32_t kMaxArgumentNesting = 32;

  PpState& state_;
  bool in_if_;
  uint32_t depth_;
  uint32_t arg_nesting_ = 0;
  uint32_t argument_of_use_ = kNoMacroUse;
  std::vector<Context> stack_;
  std::vector<ExpToken> out_;
  std::vector<PpToken>* direct_ = nullptr;
  // RunInto's source: lexed tokens converted one at a time, below every context.
  const SourceFile* source_file_ = nullptr;
  std::span<const Token> source_;
  size_t source_next_ = 0;
  bool source_has_backslash_ = false;
  size_t source_levels_ = 0;
  std::optional<ExpToken> source_peeked_;  // converted by Peek, not yet read
};

}  // namespace

std::vector<ExpToken> ExpandMacros(PpState& state, std::vector<ExpToken> input,
                                   bool in_if_expression, uint32_t depth) {
  return Expander(state, in_if_expression, depth).Run(std::move(input));
}

void ExpandMacrosInto(PpState& state, const SourceFile& file, std::span<const Token> source,
                      bool file_has_backslash, std::vector<PpToken>& out) {
  Expander(state, false, 0).RunInto(file, source, file_has_backslash, out);
}

}  // namespace shaderport::glsl
