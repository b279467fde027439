// port/precision: a default float precision in fragment shaders that have none,
// and a default for the ES 3.00 sampler types that have no default precision.
// A precision statement the user wrote is kept as it is.
//
// Before:                         After:
//   #version 300 es                 #version 300 es
//   out vec4 color;                 precision highp float;
//                                   out vec4 color;
//
// The statement goes after #version and the leading #extension lines. Without a
// #version in the file it waits for port/version to add one (next fix round),
// so the two insertions never compete for offset 0.
#include <map>
#include <set>
#include <string>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/port/port_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "port/precision";

// GLSL ES 3.00 section 4.5.4: these types have no default precision in any stage.
bool NeedsSamplerPrecision(std::string_view type) {
  static const std::set<std::string_view> kTypes = {
      "sampler3D",      "samplerCubeShadow",    "sampler2DShadow",
      "sampler2DArray", "sampler2DArrayShadow", "isampler2D",
      "isampler3D",     "isamplerCube",         "isampler2DArray",
      "usampler2D",     "usampler3D",           "usamplerCube",
      "usampler2DArray"};
  return kTypes.contains(type);
}

// The type whose default precision covers `name`: float for vectors and matrices
// of floats, int for integer vectors; samplers stand for themselves.
std::string PrecisionBaseType(std::string_view name) {
  if (name.starts_with("vec") || name.starts_with("mat")) return "float";
  if (name.starts_with("ivec") || name == "uint" || name.starts_with("uvec")) return "int";
  return std::string(name);
}

class PrecisionRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{
        kId, "Give fragment shaders a default float precision", "#version 300 es\nout vec4 color;",
        "#version 300 es\nprecision highp float;\nout vec4 color;", rule::RuleScope::kPort};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    const auto* root = context.Tree().Root();
    if (root == nullptr) return;
    // Types with a default precision at global scope (statements inside functions
    // only cover their own block).
    // A statement counts only when it comes before the type's first use: Common code
    // compiled in front of a pass that declares `precision highp float;` further down
    // uses float before any default exists (the site's header gives it one first).
    std::map<std::string, uint32_t> declared_at;
    for (const glsl::Node* node : root->declarations) {
      const auto* precision = node->As<glsl::PrecisionDeclaration>();
      if (precision != nullptr && precision->type != nullptr) {
        declared_at.emplace(precision->type->name.text, precision->range.begin);
      }
    }
    std::map<std::string, uint32_t> first_use;
    glsl::VisitPreorder(context.Tree(), [&](const glsl::Node& node, uint32_t) {
      const auto* type = node.As<glsl::TypeSpecifier>();
      if (type != nullptr && type->precision == glsl::Precision::kNone &&
          type->range.file == context.File().Id()) {
        const std::string base = PrecisionBaseType(type->name.text);
        auto [it, added] = first_use.emplace(base, type->range.begin);
        if (!added) it->second = std::min(it->second, type->range.begin);
      }
      return true;
    });
    std::set<std::string> has_default;
    for (const auto& [type, at] : declared_at) {
      const auto use = first_use.find(type);
      if (use == first_use.end() || at <= use->second) has_default.insert(type);
    }
    std::vector<std::string> missing;
    if (context.Settings().stage == model::Stage::kFragment && !has_default.contains("float")) {
      missing.push_back("float");
    }
    // shadertoy.com compiles every pass with `precision highp int;`: without it
    // int arithmetic would run at mediump in the port and change the picture.
    const model::HarnessDialect* harness = context.Settings().harness;
    if (context.Settings().stage == model::Stage::kFragment && harness != nullptr &&
        harness->NameMatches("shadertoy") && !has_default.contains("int")) {
      missing.push_back("int");
    }
    std::set<std::string> samplers;
    glsl::VisitPreorder(context.Tree(), [&](const glsl::Node& node, uint32_t) {
      const auto* type = node.As<glsl::TypeSpecifier>();
      if (type != nullptr && type->precision == glsl::Precision::kNone &&
          NeedsSamplerPrecision(type->name.text) && !has_default.contains(type->name.text)) {
        samplers.insert(type->name.text);
      }
      return true;
    });
    missing.insert(missing.end(), samplers.begin(), samplers.end());
    if (missing.empty()) return;

    bool saw_version = false;
    const uint32_t offset = webgl2::AfterLeadingDirectives(context, &saw_version);
    if (offset == 0 && !saw_version && !context.Preprocessed().version.present) return;
    std::string text;
    std::string names;
    for (const auto& type : missing) {
      text += "precision highp " + type + ";\n";
      names += (names.empty() ? "'" : ", '") + type + "'";
    }
    const FileId file = context.File().Id();
    auto diagnostic = webgl2::MakeDiagnostic(
        kId, Severity::kWarning, {file, offset, offset},
        "no default precision for " + names + ": GLSL ES 3.00 requires one; adding highp");
    diagnostic.fixes.push_back(webgl2::Insert(file, offset, std::move(text)));
    context.Report(std::move(diagnostic));
  }
};

}  // namespace

const rule::Rule& PortPrecisionRule() {
  static const PrecisionRule rule;
  return rule;
}

}  // namespace shaderport::rules
