#include "glsl/lex/pp_expression.h"

#include <cstdint>
#include <string>

#include "base/limits.h"

namespace shaderport::glsl {
namespace {

// Values are 64-bit; arithmetic wraps (through unsigned) instead of overflowing.
class Evaluator {
 public:
  Evaluator(PpState& state, std::span<const ExpToken> tokens) : state_(state), tokens_(tokens) {}

  bool Run(SourceRange directive) {
    if (tokens_.empty()) {
      Fail(directive, "#if or #elif needs an expression");
      return false;
    }
    const int64_t value = Conditional(true);
    if (!failed_ && pos_ < tokens_.size()) {
      Fail(At(), "unexpected '" + std::string(tokens_[pos_].token.text) + "' in #if expression");
    }
    return !failed_ && value != 0;
  }

 private:
  SourceRange At() const {
    return tokens_[pos_ < tokens_.size() ? pos_ : tokens_.size() - 1].token.expansion;
  }
  Punct Peek() const { return pos_ < tokens_.size() ? tokens_[pos_].token.punct : Punct::kNone; }
  bool Accept(Punct p) {
    if (failed_ || Peek() != p) return false;
    ++pos_;
    return true;
  }
  void Fail(SourceRange at, std::string message) {
    if (failed_) return;
    failed_ = true;
    state_.Report(Severity::kError, "preprocessor/invalid-if-expression", at, std::move(message));
  }

  // Guards the recursion against deeply nested input such as 100,000 '('. A level of
  // parentheses enters twice (Conditional and Unary); browsers' preprocessors stop at
  // 9,996 levels ("memory exhausted", the same 10,000-entry parser stack).
  static constexpr uint32_t kMaxDepth = 2 * (limits::kBrowserParserStack - 3);
  // Past it the shader is rejected as the parser rejects deep code (a limit breach: glslang
  // evaluates any depth).
  bool Enter() {
    if (++depth_ > kMaxDepth) {
      if (!failed_) {
        failed_ = true;
        state_.Report(Severity::kError, "syntax/nesting-too-deep", At(),
                      "#if expression nested too deeply: browsers' preprocessors give up here "
                      "('memory exhausted', after about 9,996 nested parentheses)");
      }
      return false;
    }
    return true;
  }

  int64_t Conditional(bool eval) {
    if (!Enter()) return 0;
    int64_t c = LogicalOr(eval);
    if (Accept(Punct::kQuestion)) {
      const int64_t a = Conditional(eval && c != 0);
      if (!Accept(Punct::kColon)) Fail(At(), "expected ':' in #if expression");
      const int64_t b = Conditional(eval && c == 0);
      c = c != 0 ? a : b;
    }
    --depth_;
    return c;
  }

  int64_t LogicalOr(bool eval) {
    int64_t v = LogicalAnd(eval);
    while (Accept(Punct::kOrOr)) {
      const int64_t r = LogicalAnd(eval && v == 0);
      v = (v != 0 || r != 0) ? 1 : 0;
    }
    return v;
  }

  int64_t LogicalAnd(bool eval) {
    int64_t v = BitOr(eval);
    while (Accept(Punct::kAndAnd)) {
      const int64_t r = BitOr(eval && v != 0);
      v = (v != 0 && r != 0) ? 1 : 0;
    }
    return v;
  }

  int64_t BitOr(bool eval) {
    int64_t v = BitXor(eval);
    while (Accept(Punct::kPipe)) v |= BitXor(eval);
    return v;
  }
  int64_t BitXor(bool eval) {
    int64_t v = BitAnd(eval);
    while (Accept(Punct::kCaret)) v ^= BitAnd(eval);
    return v;
  }
  int64_t BitAnd(bool eval) {
    int64_t v = Equality(eval);
    while (Accept(Punct::kAmp)) v &= Equality(eval);
    return v;
  }
  int64_t Equality(bool eval) {
    int64_t v = Relational(eval);
    while (true) {
      if (Accept(Punct::kEqualEqual)) {
        v = v == Relational(eval);
      } else if (Accept(Punct::kNotEqual)) {
        v = v != Relational(eval);
      } else {
        return v;
      }
    }
  }
  int64_t Relational(bool eval) {
    int64_t v = Shift(eval);
    while (true) {
      if (Accept(Punct::kLess)) {
        v = v < Shift(eval);
      } else if (Accept(Punct::kGreater)) {
        v = v > Shift(eval);
      } else if (Accept(Punct::kLessEqual)) {
        v = v <= Shift(eval);
      } else if (Accept(Punct::kGreaterEqual)) {
        v = v >= Shift(eval);
      } else {
        return v;
      }
    }
  }
  int64_t Shift(bool eval) {
    int64_t v = Additive(eval);
    while (true) {
      if (Accept(Punct::kShiftLeft)) {
        v = static_cast<int64_t>(static_cast<uint64_t>(v) << (Additive(eval) & 63));
      } else if (Accept(Punct::kShiftRight)) {
        v = v >> (Additive(eval) & 63);
      } else {
        return v;
      }
    }
  }
  int64_t Additive(bool eval) {
    int64_t v = Multiplicative(eval);
    while (true) {
      if (Accept(Punct::kPlus)) {
        v = static_cast<int64_t>(static_cast<uint64_t>(v) +
                                 static_cast<uint64_t>(Multiplicative(eval)));
      } else if (Accept(Punct::kMinus)) {
        v = static_cast<int64_t>(static_cast<uint64_t>(v) -
                                 static_cast<uint64_t>(Multiplicative(eval)));
      } else {
        return v;
      }
    }
  }
  int64_t Multiplicative(bool eval) {
    int64_t v = Unary(eval);
    while (true) {
      const bool mul = Accept(Punct::kStar);
      const bool div = !mul && Accept(Punct::kSlash);
      const bool mod = !mul && !div && Accept(Punct::kPercent);
      if (!mul && !div && !mod) return v;
      const SourceRange at = tokens_[pos_ - 1].token.expansion;
      const int64_t r = Unary(eval);
      if (mul) {
        v = static_cast<int64_t>(static_cast<uint64_t>(v) * static_cast<uint64_t>(r));
      } else if (r == 0) {
        if (eval) Fail(at, "division by zero in #if expression");
        v = 0;
      } else if (r == -1) {
        v = div ? static_cast<int64_t>(0 - static_cast<uint64_t>(v)) : 0;
      } else {
        v = div ? v / r : v % r;
      }
    }
  }
  int64_t Unary(bool eval) {
    if (!Enter()) return 0;
    int64_t v = 0;
    if (Accept(Punct::kPlus)) {
      v = Unary(eval);
    } else if (Accept(Punct::kMinus)) {
      v = static_cast<int64_t>(0 - static_cast<uint64_t>(Unary(eval)));
    } else if (Accept(Punct::kTilde)) {
      v = ~Unary(eval);
    } else if (Accept(Punct::kBang)) {
      v = Unary(eval) == 0;
    } else {
      v = Primary(eval);
    }
    --depth_;
    return v;
  }
  int64_t Primary(bool eval) {
    if (failed_) return 0;
    if (pos_ >= tokens_.size()) {
      Fail(At(), "#if expression ends too early");
      return 0;
    }
    if (Accept(Punct::kLeftParen)) {
      const int64_t v = Conditional(eval);
      if (!Accept(Punct::kRightParen)) Fail(At(), "expected ')' in #if expression");
      return v;
    }
    const PpToken& t = tokens_[pos_].token;
    if (t.kind == TokenKind::kIntLiteral || t.kind == TokenKind::kUintLiteral) {
      ++pos_;
      return ParseInteger(t.text);
    }
    if (t.kind == TokenKind::kIdentifier) {
      // ESSL 3.00 section 3.4: undefined identifiers do not default to 0.
      if (eval) Fail(t.expansion, "'" + std::string(t.text) + "' is not a defined macro");
      ++pos_;
      return 0;
    }
    Fail(t.expansion, "unexpected '" + std::string(t.text) + "' in #if expression");
    return 0;
  }

  static int64_t ParseInteger(std::string_view text) {
    if (!text.empty() && (text.back() == 'u' || text.back() == 'U')) text.remove_suffix(1);
    uint64_t base = 10;
    size_t i = 0;
    if (text.size() > 1 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) {
      base = 16, i = 2;
    } else if (text.size() > 1 && text[0] == '0') {
      base = 8, i = 1;
    }
    uint64_t v = 0;
    for (; i < text.size(); ++i) {
      const char c = text[i];
      const uint64_t digit = c <= '9' ? c - '0' : (c | 0x20) - 'a' + 10;
      v = v * base + digit;
    }
    return static_cast<int64_t>(v);
  }

  PpState& state_;
  std::span<const ExpToken> tokens_;
  size_t pos_ = 0;
  uint32_t depth_ = 0;
  bool failed_ = false;
};

}  // namespace

bool EvaluateCondition(PpState& state, std::span<const ExpToken> tokens, SourceRange directive) {
  return Evaluator(state, tokens).Run(directive);
}

}  // namespace shaderport::glsl
