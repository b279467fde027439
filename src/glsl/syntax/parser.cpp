// Token access, ranges, diagnostics, recovery and scopes of the parser.
#include <algorithm>
#include <string>

#include "base/large_stack.h"
#include "base/limits.h"
#include "glsl/lex/lexer.h"
#include "glsl/syntax/parser_internal.h"
#include "glsl/syntax/visit.h"

namespace shaderport::glsl {

Parser::Parser(const PreprocessResult& pp, const ParseOptions& options)
    : pp_(pp), options_(options) {
  // Token texts are read as the preprocessor left them: it already removed the line
  // continuations inside tokens (ConvertToPpToken, predefined macros, pastes), so the
  // parser keeps no cleaned copy of its own.
  const std::vector<PpToken>* tokens = &pp_.tokens;
  const auto size = static_cast<uint32_t>(tokens->size());
  // One pass finds the end of file and classifies the words before it (a token is
  // larger than a cache line's share: a second pass would read them all again).
  // Sized once and written in place (zero is a plain identifier's WordInfo).
  words_.resize(size + 1);
  end_index_ = size;
  for (uint32_t i = 0; i < size; ++i) {
    const PpToken& token = (*tokens)[i];
    if (token.kind == TokenKind::kIdentifier) {
      words_[i] = ClassifyWord(token.text, options_.version);
    } else if (token.kind == TokenKind::kEndOfFile) {
      end_index_ = i;
      break;
    }
  }
  if (end_index_ == size) {
    // No end of file (a hand-made token list): a copy ending in one, so that every
    // index up to end_index_ can be read without a bounds test.
    own_tokens_ = pp_.tokens;
    own_tokens_.emplace_back();
    tokens = &own_tokens_;
  }
  tokens_ = tokens->data();
  current_ = tokens_;
  token_count_ = static_cast<uint32_t>(tokens->size());
}

// ------------------------------------------------------------------ tokens

bool Parser::Expect(Punct p, std::string_view context) {
  if (Accept(p)) return true;
  std::string message = "expected '" + std::string(PunctSpelling(p)) + "'";
  if (!context.empty()) message += " " + std::string(context);
  if (p == Punct::kSemicolon) {
    ErrorAfterPrevious("syntax/expected-token", message);
  } else {
    ErrorAtToken("syntax/expected-token", message + ", found " + Describe());
  }
  return false;
}

Name Parser::TakeName() {
  Name name{std::string(Text()), Tok().expansion};
  if (Word().status == WordStatus::kReserved) {
    Error(name.range, "syntax/reserved-word",
          "'" + name.text + "' is a reserved word in GLSL ES " +
              (options_.version >= 300 ? "3.00" : "1.00"));
  }
  Advance();
  return name;
}

Name Parser::ExpectName(std::string_view what) {
  if (AtName()) return TakeName();
  std::string message = "expected " + std::string(what) + ", found " + Describe();
  if (Tok().kind == TokenKind::kIdentifier)
    message = "expected " + std::string(what) + ", found keyword '" + std::string(Text()) + "'";
  ErrorAtToken("syntax/expected-identifier", message);
  return Name{"", RangeOf(Index(), Index() - 1)};
}

std::string Parser::Describe(uint32_t ahead) const {
  if (Tok(ahead).kind == TokenKind::kEndOfFile) return "end of file";
  return "'" + std::string(Text(ahead)) + "'";
}

// ------------------------------------------------------------------ ranges

SourceRange Parser::RangeOf(uint32_t first, uint32_t last) const {
  SourceRange start = TokenRange(std::min(first, end_index_));
  if (last < first || last >= end_index_) return {start.file, start.begin, start.begin};
  uint32_t end_token = last;
  while (end_token > first && TokenRange(end_token).file != start.file) --end_token;
  return {start.file, start.begin, std::max(start.begin, TokenRange(end_token).end)};
}

void Parser::FinishNodeSlow(Node* node) {
  took_slow_finish_ = true;
  bool empty = pos_ <= node->first_token;
  node->last_token = empty ? node->first_token - 1 : pos_ - 1;
  node->range = RangeOf(node->first_token, node->last_token);
}

// ------------------------------------------------------------ diagnostics

void Parser::Error(const SourceRange& range, std::string_view rule, std::string message) {
  if (error_count_ >= limits::kMaxDiagnosticsPerFile) {
    if (!too_many_reported_) {
      too_many_reported_ = true;
      diagnostics_.push_back({Severity::kNote,
                              "syntax/too-many-errors",
                              range,
                              "too many syntax errors; further ones are not reported",
                              {},
                              {}});
    }
    return;
  }
  ++error_count_;
  diagnostics_.push_back({Severity::kError, std::string(rule), range, std::move(message), {}, {}});
}

void Parser::ErrorAtToken(std::string_view rule, std::string message) {
  // One error per token: the first explains it, the rest would be cascades.
  if (last_error_index_ == Index()) return;
  last_error_index_ = Index();
  Error(AtEnd() ? RangeOf(Index(), Index() - 1) : Tok().expansion, rule, std::move(message));
}

void Parser::ErrorAfterPrevious(std::string_view rule, std::string message) {
  if (last_error_index_ == Index()) return;
  last_error_index_ = Index();
  SourceRange range = pos_ > 0 ? TokenRange(pos_ - 1) : RangeOf(0, UINT32_MAX);
  range.begin = range.end;
  Error(range, rule, std::move(message));
}

bool Parser::TooDeep() {
  if (browser_stack_ <= limits::kBrowserParserStack && depth_ <= limits::kBrowserParserStack) {
    return false;
  }
  // Reported once, past the cap on errors too: a limit breach decides what runs next
  // (docs/limits.md), and thousands of errors can come before it.
  if (!depth_reported_) {
    depth_reported_ = true;
    diagnostics_.push_back(
        {Severity::kError,
         "syntax/nesting-too-deep",
         AtEnd() ? RangeOf(Index(), Index() - 1) : Tok().expansion,
         "nesting too deep: browsers' parsers give up here ('memory exhausted': more than " +
             std::to_string(limits::kBrowserParserStack) +
             " entries on their stack, about 9,990 nested parentheses or 1,665 nested 'if's)",
         {},
         {}});
  }
  return true;
}

ErrorExpr* Parser::MakeErrorExpr() {
  auto* node = Start<ErrorExpr>();
  return Finish(node);
}

static bool IsOpener(const PpToken& t) {
  return t.kind == TokenKind::kPunctuator &&
         (t.punct == Punct::kLeftParen || t.punct == Punct::kLeftBracket ||
          t.punct == Punct::kLeftBrace);
}

static bool IsCloser(const PpToken& t) {
  return t.kind == TokenKind::kPunctuator &&
         (t.punct == Punct::kRightParen || t.punct == Punct::kRightBracket ||
          t.punct == Punct::kRightBrace);
}

void Parser::SkipBalanced(bool statement) {
  uint32_t level = 0;
  while (!AtEnd()) {
    const PpToken& t = Tok();
    if (IsOpener(t)) {
      ++level;
    } else if (IsCloser(t)) {
      if (level == 0) return;
      --level;
      if (level == 0 && statement && t.punct == Punct::kRightBrace) {
        Advance();
        return;
      }
    } else if (level == 0 && t.kind == TokenKind::kPunctuator && t.punct == Punct::kSemicolon) {
      if (statement) Advance();
      return;
    }
    Advance();
  }
}

void Parser::RecoverToStatementEnd() {
  uint32_t start = pos_;
  uint32_t level = 0;
  while (!AtEnd()) {
    const PpToken& t = Tok();
    if (level == 0 && pos_ != start && t.at_line_start && t.kind == TokenKind::kIdentifier) {
      WordRole role = Word().role;
      if (role == WordRole::kType || role == WordRole::kQualifier || role == WordRole::kStruct ||
          role == WordRole::kPrecision || role == WordRole::kControl) {
        return;
      }
    }
    if (IsOpener(t)) {
      ++level;
    } else if (IsCloser(t)) {
      if (level == 0) {
        // A stray closer at the start would stop recovery forever: consume it.
        if (pos_ == start && t.punct != Punct::kRightBrace) Advance();
        return;
      }
      --level;
      if (level == 0 && t.punct == Punct::kRightBrace) {
        Advance();
        return;
      }
    } else if (level == 0 && t.kind == TokenKind::kPunctuator && t.punct == Punct::kSemicolon) {
      Advance();
      return;
    }
    Advance();
  }
}

// ------------------------------------------------------------------ scopes

bool Parser::IsStructName(std::string_view name) const {
  for (auto it = scope_names_.rbegin(); it != scope_names_.rend(); ++it) {
    if (it->first == name) return it->second;
  }
  return false;
}

bool Parser::IsTypeName(uint32_t ahead) const {
  if (Tok(ahead).kind != TokenKind::kIdentifier) return false;
  const WordInfo& word = Word(ahead);
  if (word.status == WordStatus::kKeyword) return word.role == WordRole::kType;
  return IsStructName(Text(ahead));
}

void Parser::DeclareStruct(std::string_view name) {
  if (!name.empty()) scope_names_.emplace_back(std::string(name), true);
}

void Parser::DeclareOrdinaryName(std::string_view name) {
  if (IsStructName(name)) scope_names_.emplace_back(std::string(name), false);
}

void Parser::PopScope() {
  if (scope_marks_.empty()) return;
  scope_names_.resize(scope_marks_.back());
  scope_marks_.pop_back();
}

// -------------------------------------------------------------------- run

void Parser::PlaceEmptyNodes() {
  // A missing operand sits at the next token, which may lie past its parent
  // (`float a = ;`): move each empty node into its parent so ranges nest. A loop over
  // the preorder index (parents come before their children, so each parent is placed
  // before its children are) with the open ancestors by depth, not a second walk.
  // Empty nodes come only from error recovery, through FinishNodeSlow: most trees
  // never take it, and then not even the scan of the node table is needed.
  if (!took_slow_finish_) return;
  bool any_empty = false;
  for (uint32_t id = 0; id < tree_.NodeCount() && !any_empty; ++id) {
    any_empty = !tree_.NodeAt(id).HasTokens();
  }
  if (!any_empty) return;
  std::vector<const Node*> ancestors;
  for (const PreorderEntry& entry : tree_.Preorder()) {
    ancestors.resize(entry.depth);
    ancestors.push_back(entry.node);
    if (entry.depth == 0) continue;
    const Node& parent = *ancestors[entry.depth - 1];
    const Node& child = *entry.node;
    if (child.HasTokens() || child.range.file != parent.range.file) continue;
    Node& node = tree_.NodeAt(child.id);
    uint32_t at = std::clamp(node.range.begin, parent.range.begin, parent.range.end);
    node.range.begin = node.range.end = at;
  }
}

ParseResult Parser::Run() {
  // About one node for every two tokens in shaders: the node table rarely grows.
  tree_.Reserve(end_index_ / 2 + 1);
  auto* unit = Start<TranslationUnit>();
  unit->first_token = 0;
  while (!AtEnd()) {
    uint32_t before = pos_;
    Node* decl = ParseExternalDeclaration();
    if (decl != nullptr) unit->declarations.push_back(decl);
    if (pos_ == before) Advance();  // progress guarantee: every iteration eats a token
  }
  Finish(unit);
  tree_.SetRoot(unit);
  tree_.IndexPreorder();
  PlaceEmptyNodes();
  return ParseResult{std::move(tree_), std::move(diagnostics_)};
}

ParseResult Parse(const PreprocessResult& tokens, const ParseOptions& options) {
  // Code browsers accept nests thousands of levels deep (limits::kBrowserParserStack),
  // past what a default thread stack holds: parse on a large stack (in place when the
  // caller already runs on one).
  ParseResult result;
  const auto parse = [&] {
    Parser parser(tokens, options);
    result = parser.Run();
  };
  if (!RunOnLongLivedLargeStack(parse)) parse();
  return result;
}

}  // namespace shaderport::glsl
