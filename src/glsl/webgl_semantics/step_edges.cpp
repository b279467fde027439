// smoothstep(a, b, x) with a == b: GLSL leaves the result undefined; GPUs (and
// SwiftShader in Chromium) compute (x - a) / 0 = +-inf and clamp it, i.e. a step,
// but llvmpipe folds the division under fast-math assumptions and draws garbage.
// Calls of the built-in are renamed to shaderport_smoothstep, whose a == b case is
// the step a browser draws (0 where x <= a, 1 where x > a; measured in Chromium),
// turned round when b - a is -0.0 (a = +0.0, b = -0.0, as `0.5 * fwidth(d)` can give):
// (x - a) / -0.0 is -inf where x > a.
// The name is also renamed inside macro bodies (`#define S(x, w) smoothstep(-w, w, x)`):
// there it can only mean the built-in. Nothing is renamed when a call is outside a
// function body (a constant initializer may call the built-in, not a function).
// For a render that goes through the browser's optimiser (spirv-opt -O), the helper
// hides its arguments and result behind an opaque zero: the built-in is one
// instruction there, whose arithmetic no folding rule sees ((x - a) / (b - a) with
// constant edges would become a multiplication by the reciprocal).
#include <set>
#include <utility>

#include "glsl/sema/language.h"
#include "glsl/syntax/visit.h"
#include "glsl/webgl_semantics/cpu_math_library.h"
#include "glsl/webgl_semantics/semantics_context.h"

namespace shaderport::glsl {
namespace {

constexpr std::string_view kName = "shaderport_smoothstep";

// `@` stands for the vector type of each overload. Selects are mix, not `?:` or `if`,
// which Mesa's front end compiles as branches (a large part of a call-heavy pass's compile).
constexpr std::string_view kScalarHelper =
    "float shaderport_smoothstep(float a, float b, float x) { float t = clamp((x - a) / (b - a), "
    "0.0, 1.0); return mix(t * t * (3.0 - 2.0 * t), mix(float(x > a), float(x < a), "
    "floatBitsToInt(b - a) < 0), a == b); } ";
constexpr std::string_view kVectorHelpers =
    "@ shaderport_smoothstep(@ a, @ b, @ x) { @ t = clamp((x - a) / (b - a), 0.0, 1.0); t = t * "
    "t * (3.0 - 2.0 * t); return mix(t, mix(@(greaterThan(x, a)), @(lessThan(x, a)), "
    "lessThan(floatBitsToInt(b - a), i@(0))), equal(a, b)); } "
    "@ shaderport_smoothstep(float a, float b, @ x) { return shaderport_smoothstep(@(a), @(b), "
    "x); } ";

constexpr std::string_view kOpaqueZero = "shaderport_edge_zero";

// kScalarHelper and kVectorHelpers as built-ins: arguments and results opaque.
constexpr std::string_view kOpaqueScalarHelper =
    "float shaderport_smoothstep(float a, float b, float x) { a = mix(a, -a, Z < 0.0); b = mix(b, "
    "-b, Z < 0.0); x = mix(x, -x, Z < 0.0); float t = clamp((x - a) / (b - a), 0.0, 1.0); return "
    "mix((t * t * (3.0 - 2.0 * t)) - Z, mix(float(x > a), float(x < a), floatBitsToInt(b - a) < "
    "0), a == b); } ";
constexpr std::string_view kOpaqueVectorHelpers =
    "@ shaderport_smoothstep(@ a, @ b, @ x) { a = mix(a, -a, b@(Z < 0.0)); b = mix(b, -b, b@(Z < "
    "0.0)); x = mix(x, -x, b@(Z < 0.0)); @ t = clamp((x - a) / (b - a), 0.0, 1.0); t = t * t * "
    "(3.0 - 2.0 * t); return mix(t, mix(@(greaterThan(x, a)), @(lessThan(x, a)), "
    "lessThan(floatBitsToInt(b - a), i@(0))), equal(a, b)) - Z; } "
    "@ shaderport_smoothstep(float a, float b, @ x) { return shaderport_smoothstep(@(a), @(b), "
    "x); } ";

// `@` becomes `vector`, `Z` the opaque zero.
void AppendExpanded(std::string_view pattern, std::string_view vector, std::string& text) {
  for (const char c : pattern) {
    if (c == '@') {
      text.append(vector);
    } else if (c == 'Z') {
      text.append(kOpaqueZero);
    } else {
      text.push_back(c);
    }
  }
}

std::string Helpers(bool opaque) {
  std::string text;
  if (opaque) text = "uniform highp float " + std::string(kOpaqueZero) + "; ";
  AppendExpanded(opaque ? kOpaqueScalarHelper : kScalarHelper, "", text);
  for (const std::string_view vector : {"vec2", "vec3", "vec4"}) {
    AppendExpanded(opaque ? kOpaqueVectorHelpers : kVectorHelpers, vector, text);
  }
  return MacroProofHelperText(text);
}

}  // namespace

void RewriteSmoothstepEdges(SemanticsContext& c, const PreprocessResult& preprocessed) {
  if (c.model.version < kEssl300) return;
  std::set<std::pair<FileId, uint32_t>> renamed;  // a macro body's token, once
  std::vector<SourceRange> names;
  bool safe = true;
  VisitPreorder(c.tree, [&](const Node& node, uint32_t) {
    const auto* call = node.As<CallExpr>();
    if (call == nullptr || call->call_kind != CallKind::kFunction ||
        call->callee.text != "smoothstep" || !c.model.builtin_calls.contains(call->id)) {
      return true;
    }
    if (!InsideFunctionBody(c, *call) || !call->HasTokens()) {
      safe = false;
      return true;
    }
    const PpToken& token = preprocessed.tokens[call->first_token];
    if (token.text != "smoothstep" || token.spelling.Size() != token.text.size()) {
      safe = false;  // pasted with ## or otherwise not spelled as one token
      return true;
    }
    if (renamed.insert({token.spelling.file, token.spelling.begin}).second) {
      names.push_back(token.spelling);
    }
    return true;
  });
  if (!safe) {
    c.result.skipped += static_cast<uint32_t>(names.size());
    return;
  }
  if (names.empty()) return;
  const Node* first_function = FirstFunctionDefinition(c.tree);
  const auto declare_at = first_function ? c.edits.Span(*first_function) : std::nullopt;
  if (!declare_at) {
    c.result.skipped += static_cast<uint32_t>(names.size());
    return;
  }
  c.edits.Insert(declare_at->file, declare_at->begin, Helpers(c.options.source_order_arithmetic));
  for (const SourceRange& name : names) c.edits.Replace(name, std::string(kName));
  c.result.smoothsteps = static_cast<uint32_t>(names.size());
}

}  // namespace shaderport::glsl
