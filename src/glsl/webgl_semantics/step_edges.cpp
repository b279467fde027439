// smoothstep(a, b, x) with a == b: GLSL leaves the result undefined; GPUs (and
// SwiftShader in Chromium) compute (x - a) / 0 = +-inf and clamp it, i.e. a step,
// but llvmpipe folds the division under fast-math assumptions and draws garbage.
// Calls of the built-in are renamed to shaderport_smoothstep, whose a == b case is
// the step a browser draws (0 where x <= a, 1 where x > a; measured in Chromium).
// The name is also renamed inside macro bodies (`#define S(x, w) smoothstep(-w, w, x)`):
// there it can only mean the built-in. Nothing is renamed when a call is outside a
// function body (a constant initializer may call the built-in, not a function).
#include <map>
#include <utility>

#include "glsl/sema/language.h"
#include "glsl/syntax/visit.h"
#include "glsl/webgl_semantics/cpu_math_library.h"
#include "glsl/webgl_semantics/semantics_context.h"

namespace shaderport::glsl {
namespace {

constexpr std::string_view kName = "shaderport_smoothstep";
// With constant edges when math follows Chromium (cpu_browser_math.cpp): there the
// division by the constant b - a is a multiplication by its reciprocal.
constexpr std::string_view kConstantEdgesName = "shaderport_smoothstep_k";

// `@` stands for the type of each overload, `$` for the helper's name and `/~` for
// the division by b - a.
constexpr std::string_view kScalarHelper =
    "float $(float a, float b, float x) { if (a == b) return x > a ? 1.0 : 0.0; float t = "
    "clamp((x - a) /~, 0.0, 1.0); return t * t * (3.0 - 2.0 * t); } ";
constexpr std::string_view kVectorHelpers =
    "@ $(@ a, @ b, @ x) { @ t = clamp((x - a) /~, 0.0, 1.0); t = t * t * (3.0 - 2.0 * t); "
    "return mix(t, @(greaterThan(x, a)), equal(a, b)); } "
    "@ $(float a, float b, @ x) { return $(@(a), @(b), x); } ";

std::string Helpers(std::string_view name, std::string_view divide) {
  std::string text;
  auto append = [&](std::string_view helper, std::string_view type) {
    for (size_t i = 0; i < helper.size(); ++i) {
      if (helper[i] == '@') {
        text.append(type);
      } else if (helper[i] == '$') {
        text.append(name);
      } else if (helper.compare(i, 2, "/~") == 0) {
        text.append(divide);
        ++i;
      } else {
        text.push_back(helper[i]);
      }
    }
  };
  append(kScalarHelper, "float");
  for (const std::string_view vector : {"vec2", "vec3", "vec4"}) append(kVectorHelpers, vector);
  return MacroProofHelperText(text);
}

bool ConstantEdges(const SemanticsContext& c, const CallExpr& call) {
  return c.folding != nullptr && call.arguments.size() == 3 &&
         c.folding->IsFolded(call.arguments[0]) && c.folding->IsFolded(call.arguments[1]);
}

}  // namespace

void RewriteSmoothstepEdges(SemanticsContext& c, const PreprocessResult& preprocessed) {
  if (c.model.version < kEssl300) return;
  // By spelled token (a macro body's token once): where, and whether every call
  // through it has constant edges.
  std::map<std::pair<FileId, uint32_t>, std::pair<SourceRange, bool>> names;
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
    auto [entry, added] = names.try_emplace({token.spelling.file, token.spelling.begin},
                                            token.spelling, true);
    entry->second.second = entry->second.second && ConstantEdges(c, *call);
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
  bool any_constant = false;
  for (const auto& [at, name] : names) {
    const bool constant = c.options.cpu_browser_math && name.second;
    any_constant = any_constant || constant;
    c.edits.Replace(name.first, std::string(constant ? kConstantEdgesName : kName));
  }
  std::string helpers = Helpers(kName, "/ (b - a)");
  if (any_constant) helpers += Helpers(kConstantEdgesName, "* (1.0 / (b - a))");
  c.edits.Insert(declare_at->file, declare_at->begin, helpers);
  c.result.smoothsteps = static_cast<uint32_t>(names.size());
}

}  // namespace shaderport::glsl
