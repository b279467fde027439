// Chromium without a GPU (headless, CI machines, blocklisted drivers) draws WebGL
// with SwiftShader, whose sin, cos, exp, log, pow, atan, dot, mix ... are its own
// polynomials and operation orders; llvmpipe's differ in the last bits, and hash
// noise (`fract(sin(x) * 43758.5)`) turns a last bit into a different picture. So
// calls of those built-ins become calls of helpers written as SwiftShader computes
// them (cpu_math_library.cpp). A float division by a constant becomes a
// multiplication by its reciprocal, as Chromium computes it (measured: `x / 3.3`
// gives x * float(1 / 3.3) there, even when 3.3 reaches the division through a
// variable or a parameter); Mesa divides. Every other float divisor is hidden
// behind a select on the opaque zero: Mesa's own propagation (through globals and
// struct members set in other functions) turns `x / d` with d = 0 into NaN or a
// garbage value where the browser gives +-inf
// (tests/render-parity/math/divide-by-zero.glsl). Not `d - zero`: Mesa turns
// `0.0 - zero` into `-zero`, a zero of the wrong sign.
// Left alone, as the browser folds them with exact math: calls and divisions whose
// operands reach the driver as constants (driver_folding.h), and anything outside
// a function body.
// A name spelled in a macro body is renamed only when every use of it may be.
#include <map>
#include <optional>
#include <set>
#include <utility>

#include "glsl/sema/language.h"
#include "glsl/sema/type.h"
#include "glsl/syntax/visit.h"
#include "glsl/webgl_semantics/cpu_math_library.h"
#include "glsl/webgl_semantics/semantics_context.h"

namespace shaderport::glsl {
namespace {

struct SpelledName {
  SourceRange range;
  std::string builtin;
  bool renamable = true;
  std::set<std::string> overloads;  // "min(vec3,float)", of each call spelled here
};

bool IsBoolSelect(const SemanticModel& model, const CallExpr& call) {
  if (call.callee.text != "mix" || call.arguments.size() != 3) return false;
  return model.TypeOf(call.arguments[2]->id).base == BaseType::kBool;
}

const CallExpr* UnparenthesizedCall(const Expr* expr) {
  while (expr != nullptr && expr->kind == NodeKind::kParenExpr) expr = expr->As<ParenExpr>()->inner;
  return expr != nullptr ? expr->As<CallExpr>() : nullptr;
}

bool IsZeroLiteral(const Expr* expr) {
  const auto* literal = expr->As<LiteralExpr>();
  return literal != nullptr && literal->literal_kind == LiteralKind::kFloat &&
         literal->float_value == 0.0;
}

enum class DivisionRewrite : uint8_t {
  kNone,           // folded whole: both compilers divide exactly
  kReciprocal,     // `x * (1.0 / (c))`
  kOpaqueDivisor,  // `x / mix((d), T(1.0), zero < 0.0)` (OpaqueSelect): Mesa cannot fold d
};

struct Division {
  SourceRange op;
  SourceRange divisor;
  DivisionRewrite rewrite = DivisionRewrite::kNone;
  std::string divisor_type;  // spelled, for kOpaqueDivisor
  bool opaque = false;       // the reciprocal passes through the opaque zero
};

struct DivisionSite {
  Division division;
  bool rewritable = true;  // every division spelled there qualifies
};

class MathRewriter {
 public:
  MathRewriter(SemanticsContext& c, const PreprocessResult& preprocessed)
      : c_(c), pp_(preprocessed) {}

  void Collect() {
    VisitPreorder(c_.tree, [&](const Node& node, uint32_t) {
      if (const auto* call = node.As<CallExpr>()) {
        CollectCall(*call);
        CollectUintConversions(*call);
        CollectFoldedClamp(*call);
        CollectModDivisor(*call);
      }
      if (const auto* binary = node.As<BinaryExpr>()) {
        if (binary->op == BinaryOp::kDiv) {
          CollectDivision(*binary, binary->lhs, binary->rhs);
          CollectPartlyZeroVector(*binary, binary->lhs);
        }
        if (binary->op == BinaryOp::kMul) {
          CollectPartlyZeroVector(*binary, binary->lhs);
          CollectPartlyZeroVector(*binary, binary->rhs);
        }
      }
      if (const auto* assignment = node.As<AssignmentExpr>()) {
        if (assignment->op == AssignOp::kDiv) {
          CollectDivision(*assignment, assignment->lhs, assignment->rhs);
        }
        if (assignment->op == AssignOp::kMul) CollectPartlyZeroVector(*assignment, assignment->rhs);
      }
      return true;
    });
  }

  void Apply() {
    const Node* first_function = FirstFunctionDefinition(c_.tree);
    const auto declare_at = first_function ? c_.edits.Span(*first_function) : std::nullopt;
    const bool zero_for_divisions = declare_at && AddDivisions();
    std::set<std::string> used;
    for (const auto& [at, name] : names_) {
      if (!name.renamable || !declare_at) {
        ++c_.result.skipped;
        continue;
      }
      used.insert(name.overloads.begin(), name.overloads.end());
      c_.edits.Replace(name.range, CpuMathHelperName(name.builtin));
      ++c_.result.math_calls;
    }
    for (const auto& [callee, helper] : folded_clamps_) {
      if (!declare_at) {
        ++c_.result.skipped;
        continue;
      }
      used.insert(helper);
      c_.edits.Replace(callee, CpuMathHelperName(helper));
      ++c_.result.folded_clamps;
    }
    if (!conversions_.empty() && declare_at) {
      used.insert("u2f");
      for (const SourceRange& argument : conversions_) {
        c_.edits.Insert(argument.file, argument.begin, "shaderport_u2f(");
        c_.edits.Insert(argument.file, argument.end, ")");
        ++c_.result.conversions;
      }
    }
    if (!used.empty() || zero_for_divisions) {
      c_.edits.Insert(declare_at->file, declare_at->begin,
                      CpuMathDefinitions(used, zero_for_divisions, !ArithmeticStaysExact(),
                                         c_.swizzle_letters));
    }
  }

 private:
  // Every value reaches an invariant output (source_order_arithmetic.cpp: data through
  // the outputs, branches through the probe), so Mesa regroups none of it.
  bool ArithmeticStaysExact() const {
    const BrowserSemanticsOptions& o = c_.options;
    return o.source_order_arithmetic && o.add_render_probe && !o.vertex_stage &&
           !o.opaque_helper_arguments && c_.model.version >= kEssl300;
  }

  // `x / c` becomes `x * (1.0 / (c))`; both compilers then merge the reciprocal into
  // a chain of constant factors (`(v / 65534.0) * 1000.0`). Not through a vector
  // constructor, which the browser's optimiser does not look into and Mesa, having
  // split the vector, does: `vec2(a, v * 0.3) / 65534.0` becomes
  // `vec2(a, v * 0.3) * ((1.0 / (65534.0)) - zero)`. Returns whether the zero is used.
  bool AddDivisions() {
    bool opaque = false;
    const std::string zero(kOpaqueZeroUniform);
    // Innermost first: a division inside another's divisor ends where that divisor ends,
    // and its closing text must come first there.
    // (Not std::views::reverse: clang 14 cannot build it with libstdc++ 12.)
    for (auto entry = divisions_.rbegin(); entry != divisions_.rend();  // NOLINT
         ++entry) {
      const DivisionSite& site = entry->second;
      if (!site.rewritable) continue;
      const Division& division = site.division;
      const SourceRange& divisor = division.divisor;
      if (division.rewrite == DivisionRewrite::kOpaqueDivisor) {
        // OpaqueSelect's text split around the divisor.
        const std::string one = division.divisor_type + "(1.0)";
        const std::string select = OpaqueSelect(division.divisor_type, zero, "(@)", one);
        const size_t hole = select.find('@');
        c_.edits.Insert(divisor.file, divisor.begin, select.substr(0, hole));
        c_.edits.Insert(divisor.file, divisor.end, select.substr(hole + 1));
        ++c_.result.opaque_divisors;
        opaque = true;
        continue;
      }
      const bool compound = division.op.Size() == 2;  // `/=`
      c_.edits.Replace(division.op, compound ? "*=" : "*");
      c_.edits.Insert(divisor.file, divisor.begin, division.opaque ? "((1.0 / (" : "(1.0 / (");
      c_.edits.Insert(divisor.file, divisor.end, division.opaque ? ")) - " + zero + ")" : "))");
      ++c_.result.divisions;
      opaque = opaque || division.opaque;
    }
    // After the divisions: a division inside mod's divisor ends where it ends, and its
    // closing text must come first there. (CollectModDivisor, CollectPartlyZeroVector)
    for (const auto& [divisor, type] : hidden_operands_) {
      const std::string select = OpaqueSelect(type, zero, "(@)", type + "(1.0)");
      const size_t hole = select.find('@');
      c_.edits.Insert(divisor.file, divisor.begin, select.substr(0, hole));
      c_.edits.Insert(divisor.file, divisor.end, select.substr(hole + 1));
      ++c_.result.opaque_divisors;
      opaque = true;
    }
    return opaque;
  }

  void CollectCall(const CallExpr& call) {
    if (call.call_kind != CallKind::kFunction || !c_.model.builtin_calls.contains(call.id) ||
        !HasCpuMathDefinition(call.callee.text) || IsBoolSelect(c_.model, call) ||
        c_.model.TypeOf(call.id).base != BaseType::kFloat ||  // min, max, clamp on ints
        !call.HasTokens()) {
      return;
    }
    const PpToken& token = pp_.tokens[call.first_token];
    const bool spelled =
        token.text == call.callee.text && token.spelling.Size() == token.text.size();
    if (!spelled) {
      ++c_.result.skipped;  // pasted with ## or otherwise not one written token
      return;
    }
    auto [entry, added] = names_.try_emplace({token.spelling.file, token.spelling.begin});
    if (added) entry->second = {token.spelling, std::string(call.callee.text), true, {}};
    entry->second.overloads.insert(Overload(call));
    // A folded constant stays exact in the browser; a global initializer must stay
    // a constant expression.
    if (c_.folding->IsFolded(&call) || !InsideFunctionBody(c_, call)) {
      entry->second.renamable = false;
    }
  }

  // "min(vec3,float)"; the bare name (every overload) when a type is unknown.
  std::string Overload(const CallExpr& call) const {
    std::string signature(call.callee.text);
    signature += '(';
    for (size_t i = 0; i < call.arguments.size(); ++i) {
      const Type& type = c_.model.TypeOf(call.arguments[i]->id);
      if (type.IsUnknown() || type.IsArray()) {
        signature.resize(call.callee.text.size());
        return signature;
      }
      if (i > 0) signature += ',';
      signature += Spell(type);
    }
    signature += ')';
    return signature;
  }

  // clamp(x, lo, hi) with x and one bound constant: the SPIR-V optimiser answers
  // from those two alone (x <= lo gives lo, x >= hi gives hi), which differs from
  // min(max(x, lo), hi) when lo > hi, as in `t += clamp(0.02, 2.0, h)`.
  void CollectFoldedClamp(const CallExpr& call) {
    if (call.call_kind != CallKind::kFunction || call.callee.text != "clamp" ||
        call.arguments.size() != 3 || !c_.model.builtin_calls.contains(call.id) ||
        !c_.model.TypeOf(call.id).IsScalar() || c_.model.TypeOf(call.id).base != BaseType::kFloat ||
        c_.folding->IsFolded(&call) || !InsideFunctionBody(c_, call)) {
      return;
    }
    const auto x = ConstantValue(call.arguments[0]);
    if (!x) return;
    const Expr* answer = nullptr;
    if (const auto lo = ConstantValue(call.arguments[1]); lo && *x <= *lo) {
      answer = call.arguments[1];
    } else if (const auto hi = ConstantValue(call.arguments[2]); hi && *x >= *hi) {
      answer = call.arguments[2];
    }
    if (answer == nullptr) return;
    // The callee is renamed to a helper returning that bound, rather than the other
    // arguments' text cut away: edits inside them (a division) would overlap the cut.
    const auto whole = c_.edits.Span(call);
    const PpToken* name = call.HasTokens() ? &pp_.tokens[call.first_token] : nullptr;
    if (!whole || name == nullptr || name->text != "clamp" ||
        name->spelling.Size() != name->text.size() || name->spelling.file != whole->file ||
        name->spelling.begin != whole->begin) {
      ++c_.result.skipped;
      return;
    }
    folded_clamps_.emplace_back(name->spelling,
                                answer == call.arguments[1] ? "clamp_lo" : "clamp_hi");
  }

  // mod(x, y) is x - y * floor(x / y) in both compilers, and Mesa folds it where y is
  // a constant 0 (in a component of a vector too) to x; the browser computes it at run
  // time and gets NaN (x / 0 is inf, 0 * inf NaN). So y is hidden from Mesa's folding
  // like a divisor, whatever its value: a hidden non-zero constant gives Chromium's
  // bits as well (measured, ShaderToy MstSDB and ldBBWm).
  void CollectModDivisor(const CallExpr& call) {
    if (call.call_kind != CallKind::kFunction || call.callee.text != "mod" ||
        call.arguments.size() != 2 || !c_.model.builtin_calls.contains(call.id) ||
        !c_.model.TypeOf(call.id).IsFloating() || c_.folding->IsFolded(&call) ||
        !InsideFunctionBody(c_, call)) {
      return;
    }
    const Expr* divisor = call.arguments[1];
    const auto span = c_.edits.Span(*divisor);
    if (!span) {
      ++c_.result.skipped;
      return;
    }
    hidden_operands_.emplace_back(*span, Spell(c_.model.TypeOf(divisor->id)));
  }

  // A vector of literals with some components 0 and some not (`vec3(0, .03, .06)`), as
  // a factor or a dividend of what is computed at run time: Mesa folds 0 * y and 0 / y
  // to 0 component by component, the browser computes them (NaN where y is inf or 0;
  // measured: ShaderToy fdcSWH's centre is black in Chromium). A vector all 0 or a
  // scalar 0 the browser folds as Mesa does, and it is left alone.
  void CollectPartlyZeroVector(const Expr& operation, const Expr* operand) {
    const CallExpr* constructor = UnparenthesizedCall(operand);
    if (constructor == nullptr || constructor->call_kind != CallKind::kConstructor ||
        !c_.model.TypeOf(constructor->id).IsVector() ||
        c_.model.TypeOf(constructor->id).base != BaseType::kFloat ||
        c_.folding->IsFolded(&operation) || !InsideFunctionBody(c_, operation)) {
      return;
    }
    bool zero = false;
    bool other = false;
    for (const Expr* argument : constructor->arguments) {
      const auto* literal = argument->As<LiteralExpr>();
      if (literal == nullptr || (literal->literal_kind != LiteralKind::kFloat &&
                                 literal->literal_kind != LiteralKind::kInt)) {
        return;
      }
      const double value = literal->literal_kind == LiteralKind::kFloat
                               ? literal->float_value
                               : static_cast<double>(literal->int_value);
      (value == 0.0 ? zero : other) = true;
    }
    if (!zero || !other || constructor->arguments.size() < 2) return;
    const auto span = c_.edits.Span(*operand);
    if (!span) {
      ++c_.result.skipped;
      return;
    }
    hidden_operands_.emplace_back(*span, Spell(c_.model.TypeOf(constructor->id)));
  }

  // The value of a float literal, possibly negated or parenthesised, or of a
  // variable the driver sees as such a constant.
  std::optional<double> ConstantValue(const Expr* expr, int depth = 0) const {
    if (expr == nullptr || depth > 8) return std::nullopt;
    if (const auto* literal = expr->As<LiteralExpr>()) {
      if (literal->literal_kind != LiteralKind::kFloat) return std::nullopt;
      return static_cast<double>(static_cast<float>(literal->float_value));
    }
    if (const auto* paren = expr->As<ParenExpr>()) return ConstantValue(paren->inner, depth + 1);
    if (const auto* unary = expr->As<UnaryExpr>(); unary && unary->op == UnaryOp::kMinus) {
      const auto value = ConstantValue(unary->operand, depth + 1);
      return value ? std::optional<double>(-*value) : std::nullopt;
    }
    if (expr->kind == NodeKind::kIdentifierExpr && c_.folding->IsFolded(expr)) {
      const uint32_t symbol = c_.model.SymbolAt(expr->id);
      const uint32_t declaration = c_.model.symbols[symbol].declaration;
      if (declaration == kNoNode) return std::nullopt;
      const auto* declarator = c_.tree.NodeAt(declaration).As<Declarator>();
      return declarator ? ConstantValue(declarator->initializer, depth + 1) : std::nullopt;
    }
    return std::nullopt;
  }

  // float(u), vec3(uvec3): SwiftShader converts a uint in two roundings.
  void CollectUintConversions(const CallExpr& call) {
    if (call.call_kind != CallKind::kConstructor || !c_.model.TypeOf(call.id).IsFloating() ||
        !InsideFunctionBody(c_, call)) {
      return;
    }
    for (const Expr* argument : call.arguments) {
      const Type& type = c_.model.TypeOf(argument->id);
      if (type.IsArray() || type.base != BaseType::kUint || c_.folding->IsFolded(argument)) {
        continue;
      }
      const auto span = c_.edits.Span(*argument);
      if (!span) {
        ++c_.result.skipped;
        continue;
      }
      conversions_.push_back(*span);
    }
  }

  void CollectDivision(const Expr& division, const Expr* dividend, const Expr* divisor) {
    if (dividend == nullptr || divisor == nullptr || !dividend->HasTokens() ||
        !InsideFunctionBody(c_, division)) {
      return;
    }
    const uint32_t op_token = dividend->last_token + 1;
    if (op_token >= pp_.tokens.size()) return;
    const PpToken& op = pp_.tokens[op_token];
    if (op.text != "/" && op.text != "/=") return;
    auto [entry, added] = divisions_.try_emplace({op.spelling.file, op.spelling.begin});
    DivisionSite& site = entry->second;
    if (added) site.division.op = op.spelling;
    const DivisionRewrite rewrite = RewriteOf(division, *divisor);
    const auto span = DivisorSpan(op, *divisor);
    const std::string type = Spell(c_.model.TypeOf(divisor->id));
    // Every division spelled at one place (a macro body) must take the same rewrite.
    if (rewrite == DivisionRewrite::kNone || !span ||
        (!added && (span->begin != site.division.divisor.begin ||
                    rewrite != site.division.rewrite || type != site.division.divisor_type))) {
      site.rewritable = false;
      return;
    }
    site.division.divisor = *span;
    site.division.rewrite = rewrite;
    site.division.divisor_type = type;
    const auto* constructor = UnparenthesizedCall(dividend);
    site.division.opaque =
        site.division.opaque ||
        (constructor != nullptr && constructor->call_kind == CallKind::kConstructor &&
         c_.model.TypeOf(constructor->id).IsVector());
  }

  // Folded whole, the division is exact in the browser too. A matrix divisor: `*`
  // would be the matrix product. A zero divisor: x * inf is x / 0 anyway.
  DivisionRewrite RewriteOf(const Expr& division, const Expr& divisor) const {
    if (!c_.model.TypeOf(division.id).IsFloating() || c_.folding->IsFolded(&division)) {
      return DivisionRewrite::kNone;
    }
    if (c_.folding->IsFolded(&divisor) && !IsZeroLiteral(&divisor) &&
        !c_.model.TypeOf(divisor.id).IsMatrix()) {
      return DivisionRewrite::kReciprocal;
    }
    return DivisionRewrite::kOpaqueDivisor;
  }

  // Where the divisor is written: in the file next to a written `/`, or, when the `/`
  // is spelled in a macro body, as tokens of that same body (an edit there changes
  // every expansion, so every one must qualify).
  std::optional<SourceRange> DivisorSpan(const PpToken& op, const Expr& divisor) const {
    if (op.macro_use == kNoMacroUse) {
      const auto span = c_.edits.Span(divisor);
      if (!span || span->file != op.spelling.file || span->begin < op.spelling.end) return {};
      return span;
    }
    if (!op.in_macro_body || !divisor.HasTokens()) return {};
    uint32_t at = op.spelling.end;
    for (uint32_t t = divisor.first_token; t <= divisor.last_token; ++t) {
      const PpToken& token = pp_.tokens[t];
      if (!token.in_macro_body || token.spelling.file != op.spelling.file ||
          token.spelling.begin < at || token.spelling.Size() != token.text.size()) {
        return {};
      }
      at = token.spelling.end;
    }
    return SourceRange{op.spelling.file, pp_.tokens[divisor.first_token].spelling.begin, at};
  }

  SemanticsContext& c_;
  const PreprocessResult& pp_;
  std::map<std::pair<FileId, uint32_t>, SpelledName> names_;
  std::map<std::pair<FileId, uint32_t>, DivisionSite> divisions_;  // by the spelled `/`
  std::vector<SourceRange> conversions_;  // uint arguments of float constructors
  std::vector<std::pair<SourceRange, std::string>> folded_clamps_;  // callee, helper
  // mod's divisors and partly zero vectors, hidden from Mesa: span, spelled type
  std::vector<std::pair<SourceRange, std::string>> hidden_operands_;
};

}  // namespace

void ComputeMathAsCpuBrowser(SemanticsContext& c, const PreprocessResult& preprocessed) {
  if (c.model.version < kEssl300) return;  // the helpers need ES 3.00's bit operations
  MathRewriter rewriter(c, preprocessed);
  rewriter.Collect();
  rewriter.Apply();
}

}  // namespace shaderport::glsl
