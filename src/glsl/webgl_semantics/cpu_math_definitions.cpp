// GLSL text of the math helpers (table in cpu_math_library.cpp): the overloads a
// shader calls and those they call, each spelled so that Mesa computes SwiftShader's bits.
#include <algorithm>
#include <array>
#include <cctype>
#include <set>
#include <string>
#include <vector>

#include "glsl/webgl_semantics/cpu_math_helpers.h"
#include "glsl/webgl_semantics/cpu_math_library.h"

namespace shaderport::glsl {
namespace {

// The table's marks expanded: `S(name)` -> `shaderport_name`, `Z` -> the opaque zero.
std::string ExpandMarks(std::string_view text) {
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == 'Z' && (i + 1 == text.size() || text[i + 1] == ')' || text[i + 1] == ' ')) {
      out.append(kOpaqueZeroUniform);
      continue;
    }
    if (text.compare(i, 2, "S(") == 0 &&
        (i == 0 ||
         (!std::isalnum(static_cast<unsigned char>(text[i - 1])) && text[i - 1] != '_'))) {
      const size_t close = text.find(')', i);
      out += "shaderport_";
      out.append(text.substr(i + 2, close - i - 2));
      i = close;
      continue;
    }
    out.push_back(text[i]);
  }
  return out;
}

constexpr std::array<std::string_view, 3> kVectors = {"vec2", "vec3", "vec4"};
constexpr std::array<char, 4> kComponents = {'x', 'y', 'z', 'w'};

// kReduction/kGeometric: `@` is the type; the part between the two `#`-free ends
// repeats: "head# body with # ...; tail" -> the body once per component after the
// first, `#` replaced by the component.
std::string ForSize(std::string_view text, std::string_view type, int size) {
  std::string typed;
  for (const char c : text) {
    if (c == '@') {
      typed.append(type);
    } else {
      typed.push_back(c);
    }
  }
  const size_t first = typed.find('#');
  if (first == std::string::npos) return typed;
  const size_t end = typed.find(';', typed.rfind('#'));
  const std::string head = typed.substr(0, first);
  const std::string body = typed.substr(first + 1, end + 1 - first - 1);
  std::string out = head;
  for (int i = 1; i < size; ++i) {
    for (const char c : body) {
      if (c == '#') {
        out.push_back(kComponents[static_cast<size_t>(i)]);
      } else {
        out.push_back(c);
      }
    }
  }
  out += typed.substr(end + 1);
  return out;
}

// Componentwise vector overloads of a float helper with `arity` float parameters;
// with `float_tail` > 0 also the overload whose last `float_tail` parameters are
// floats (mix(vec3, vec3, float), clamp(vec3, float, float)).
std::string Componentwise(std::string_view name, int arity, int float_tail) {
  std::string out;
  const std::string helper = "shaderport_" + std::string(name);
  for (size_t v = 0; v < kVectors.size(); ++v) {
    const std::string_view type = kVectors[v];
    const int size = static_cast<int>(v) + 2;
    for (int variant = 0; variant < (float_tail > 0 ? 2 : 1); ++variant) {
      const int first_float = variant == 1 ? arity - float_tail : arity;
      out += " " + std::string(type) + " " + helper + "(";
      for (int p = 0; p < arity; ++p) {
        const bool is_float = p >= first_float;
        out +=
            (p > 0 ? ", " : "") + std::string(is_float ? "float" : type) + " a" + std::to_string(p);
      }
      out += ") { return " + std::string(type) + "(";
      for (int c = 0; c < size; ++c) {
        out += (c > 0 ? ", " : "") + helper + "(";
        for (int p = 0; p < arity; ++p) {
          const bool is_float = p >= first_float;
          out += (p > 0 ? ", " : "") + ("a" + std::to_string(p)) +
                 (is_float ? "" : std::string(".") + kComponents[static_cast<size_t>(c)]);
        }
        out += ")";
      }
      out += "); }";
    }
  }
  return out;
}

// Each parameter of each function in `text` starts with `p = mix(p, -p, zero < 0.0);`
// (OpaqueSelect: `-p` where the always-0 uniform is negative, which Mesa cannot rule
// out) and each `return x;` becomes `return (x) - zero;`: in Chromium the helper's arithmetic
// runs inside SwiftShader, out of reach of the SPIR-V optimiser, so Mesa must not mix
// the caller's arithmetic into it either (it turns `(v * 0.61) * 78.233` into
// `v * 47.72`, `v * a + v * b` into `v * (a + b)`, `(p * x) * k` into `(p * k) * x`).
// Parameters do not use `p - zero`: Mesa turns `0.0 - zero` into `-zero`, a zero of
// the wrong sign (atan(0.0, x) flipped); a result is never a constant, since no
// constant reaches the helper. Multiplying results by a select changed 10 pictures
// of the shared corpus (measured), so they keep `- zero`. Without `parameters` only
// the results are: where every value reaches an invariant output, Mesa keeps the
// caller's arithmetic exact anyway, and the selects made a quarter of the compile.
std::string WithOpaqueParameters(std::string_view text, bool parameters) {
  constexpr std::string_view kReturn = "return ";
  std::string out;
  int depth = 0;
  for (size_t i = 0; i < text.size();) {
    if (depth > 0 && text.compare(i, kReturn.size(), kReturn) == 0) {
      const size_t end = text.find(';', i);
      out += "return (";
      out.append(text.substr(i + kReturn.size(), end - i - kReturn.size()));
      out += ") - " + std::string(kOpaqueZeroUniform);
      i = end;
      continue;
    }
    if (depth == 0 && text[i] == '(') {
      const size_t close = text.find(')', i);
      const size_t brace = text.find('{', close);
      const std::string_view list = text.substr(i + 1, close - i - 1);
      out.append(text.substr(i, brace + 1 - i));
      for (size_t begin = 0; parameters && begin < list.size();) {
        size_t end = list.find(',', begin);
        if (end == std::string_view::npos) end = list.size();
        const std::string_view parameter = list.substr(begin, end - begin);
        const size_t space = parameter.rfind(' ');
        const std::string name(parameter.substr(space + 1));
        const size_t type_begin = parameter.find_first_not_of(' ');
        const std::string_view type = parameter.substr(type_begin, space - type_begin);
        out.append(" ").append(name).append(" = ");
        out.append(OpaqueSelect(type, kOpaqueZeroUniform, name, "-" + name)).append(";");
        begin = end + 1;
      }
      i = brace + 1;
      depth = 1;
      continue;
    }
    if (text[i] == '{') ++depth;
    if (text[i] == '}') --depth;
    out.push_back(text[i++]);
  }
  return out;
}

// The vector overloads of `helper.vector_text` for vec2, vec3 and vec4.
std::string WholeVectorOverloads(const Helper& helper) {
  std::string out;
  for (size_t v = 0; v < kVectors.size(); ++v) {
    const std::string size = std::to_string(v + 2);
    for (const char c : helper.vector_text) {
      if (c == '@') {
        out += "vec" + size;
      } else if (c == '$') {
        out += "ivec" + size;
      } else if (c == '%') {
        out += "uvec" + size;
      } else {
        out.push_back(c);
      }
    }
    out.push_back(' ');
  }
  return ExpandMarks(out);
}

// One function of a helper, with what it calls: (helper, type of its first parameter).
struct Overload {
  std::string_view helper;
  std::vector<std::string> parameters;  // types
  std::string text;
  std::vector<std::pair<std::string_view, std::string>> needs;
};

std::vector<std::string> ParameterTypes(std::string_view function) {
  std::vector<std::string> types;
  const size_t open = function.find('(');
  const std::string_view list = function.substr(open + 1, function.find(')', open) - open - 1);
  for (size_t begin = 0; begin < list.size();) {
    size_t end = list.find(',', begin);
    if (end == std::string_view::npos) end = list.size();
    const size_t first = list.find_first_not_of(' ', begin);
    types.emplace_back(list.substr(first, std::min(list.find(' ', first), end) - first));
    begin = end + 1;
  }
  return types;
}

// Splits `text`, definitions one after another, into `out`. A componentwise function
// calls the helper's own scalar overloads; any other calls the helpers it lists with
// its own first parameter type (dot(vec3, vec3) from reflect(vec3, vec3)).
void AddFunctions(const Helper& helper, const std::string& text, bool componentwise,
                  std::vector<Overload>& out) {
  size_t begin = text.find_first_not_of(' ');
  int depth = 0;
  for (size_t i = begin; i < text.size(); ++i) {
    if (text[i] == '{') ++depth;
    if (text[i] != '}' || --depth != 0) continue;
    Overload overload{helper.builtin, {}, text.substr(begin, i + 1 - begin), {}};
    overload.parameters = ParameterTypes(overload.text);
    const std::string first = overload.parameters.empty() ? "" : overload.parameters.front();
    if (componentwise) {
      overload.needs.emplace_back(helper.builtin, first.starts_with("u") ? "uint" : "float");
    } else {
      for (const std::string_view call : helper.calls) overload.needs.emplace_back(call, first);
    }
    out.push_back(std::move(overload));
    begin = text.find_first_not_of(' ', i + 1);
    if (begin == std::string::npos) break;
    i = begin - 1;
  }
}

// The float overload and the vector overloads: on whole vectors where the helper has
// them, else componentwise (with `float_tail` trailing float parameters too).
void AddFloatAndVectorOverloads(const Helper& helper, int arity, int float_tail,
                                bool opaque_parameters, std::vector<Overload>& out) {
  AddFunctions(helper, WithOpaqueParameters(ExpandMarks(helper.text), opaque_parameters), false,
               out);
  if (!helper.vector_text.empty()) {
    AddFunctions(helper, WithOpaqueParameters(WholeVectorOverloads(helper), opaque_parameters),
                 false, out);
  } else {
    AddFunctions(helper, Componentwise(helper.builtin, arity, float_tail), true, out);
  }
}

std::vector<Overload> Overloads(const Helper& helper, bool opaque_parameters) {
  std::vector<Overload> out;
  switch (helper.shape) {
    case Shape::kInternal:
      AddFunctions(helper, ExpandMarks(helper.text), false, out);
      if (!helper.vector_text.empty()) {
        AddFunctions(helper, WholeVectorOverloads(helper), false, out);
      }
      break;
    case Shape::kFromUint: {
      AddFunctions(helper, ExpandMarks(helper.text), false, out);
      std::string vectors;
      for (size_t v = 0; v < kVectors.size(); ++v) {
        const std::string type(kVectors[v]);
        vectors.append(" ").append(type).append(" shaderport_u2f(u").append(type);
        vectors.append(" a) { return ").append(type).append("(");
        for (size_t c = 0; c <= v + 1; ++c) {
          vectors += std::string(c > 0 ? ", " : "") + "shaderport_u2f(a." + kComponents[c] + ")";
        }
        vectors += "); }";
      }
      AddFunctions(helper, vectors, true, out);
      break;
    }
    case Shape::kUnary:
      AddFloatAndVectorOverloads(helper, 1, 0, opaque_parameters, out);
      if (helper.builtin == "atan") {
        AddFunctions(helper, Componentwise(helper.builtin, 2, 0), true, out);
      }
      break;
    case Shape::kBinary:
      AddFloatAndVectorOverloads(helper, 2, 0, opaque_parameters, out);
      break;
    case Shape::kMinMax:
      AddFloatAndVectorOverloads(helper, 2, 1, opaque_parameters, out);
      break;
    case Shape::kMix:
      // Always opaque: without, Mesa still reshaped mix's arithmetic with the caller's
      // (4sXcWj drew 23 of 64 blocks off Chromium's; the selects of the others made no
      // difference there).
      AddFloatAndVectorOverloads(helper, 3, 1, true, out);
      break;
    case Shape::kReduction:
    case Shape::kGeometric: {
      std::string text = WithOpaqueParameters(
          ExpandMarks(helper.float_text.empty() ? ForSize(helper.text, "float", 1)
                                                : helper.float_text),
          opaque_parameters);
      for (size_t v = 0; v < kVectors.size(); ++v) {
        text += " " + WithOpaqueParameters(
                          ExpandMarks(ForSize(helper.text, kVectors[v], static_cast<int>(v) + 2)),
                          opaque_parameters);
      }
      AddFunctions(helper, text, false, out);
      break;
    }
  }
  return out;
}

void AddWithCalls(std::string_view name, std::vector<const Helper*>& ordered,
                  std::set<std::string_view>& seen) {
  const Helper* helper = FindCpuMathHelper(name);
  if (helper == nullptr || !seen.insert(helper->builtin).second) return;
  for (const std::string_view call : helper->calls) AddWithCalls(call, ordered, seen);
  ordered.push_back(helper);  // after what it calls
}

}  // namespace

std::string CpuMathDefinitions(const std::set<std::string>& overloads, bool declare_zero,
                               bool opaque_parameters, std::string_view swizzle_letters) {
  auto name_of = [](const std::string& request) {
    return std::string_view(request).substr(0, request.find('('));
  };
  std::vector<const Helper*> ordered;
  std::set<std::string_view> seen;
  for (const std::string& request : overloads) AddWithCalls(name_of(request), ordered, seen);
  std::vector<Overload> all;
  for (const Helper* helper : ordered) {
    for (Overload& overload : Overloads(*helper, opaque_parameters)) {
      all.push_back(std::move(overload));
    }
  }
  std::vector<bool> keep(all.size(), false);
  std::vector<size_t> pending;
  auto mark = [&](size_t i) {
    if (!keep[i]) pending.push_back(i);
    keep[i] = true;
  };
  for (const std::string& request : overloads) {
    const std::string_view name = name_of(request);
    const bool typed = request.size() > name.size();
    const std::vector<std::string> types =
        typed ? ParameterTypes(std::string_view(request)) : std::vector<std::string>{};
    bool found = false;
    for (size_t i = 0; i < all.size(); ++i) {
      if (all[i].helper == name && (!typed || all[i].parameters == types)) {
        mark(i);
        found = true;
      }
    }
    for (size_t i = 0; !found && i < all.size(); ++i) {
      if (all[i].helper == name) mark(i);  // no such overload: all of them
    }
  }
  while (!pending.empty()) {
    const size_t at = pending.back();
    pending.pop_back();
    for (const auto& [helper, first] : all[at].needs) {
      for (size_t i = 0; i < all.size(); ++i) {
        if (all[i].helper == helper && !all[i].parameters.empty() &&
            all[i].parameters.front() == first) {
          mark(i);
        }
      }
    }
  }
  std::string text;
  for (size_t i = 0; i < all.size(); ++i) {
    if (keep[i]) text += all[i].text + " ";
  }
  if (declare_zero || text.find(kOpaqueZeroUniform) != std::string::npos) {
    text = "uniform highp float " + std::string(kOpaqueZeroUniform) + "; " + text;
  }
  return MacroProofHelperText(text, swizzle_letters);
}

}  // namespace shaderport::glsl
