// webgl2/precision: a default float precision in fragment shaders that have none,
// and a default for the ES 3.00 sampler types that have no default precision.
// A precision statement the user wrote is kept as it is.
//
// Before:                         After:
//   #version 300 es                 #version 300 es
//   out vec4 color;                 precision highp float;
//                                   out vec4 color;
//
// The statement goes after #version and the leading #extension lines. Without a
// #version in the file it waits for webgl2/version to add one (next fix round),
// so the two insertions never compete for offset 0.
#include <set>
#include <string>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/webgl2/webgl2_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "webgl2/precision";

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
    std::set<std::string> has_default;
    for (const glsl::Node* node : root->declarations) {
      const auto* precision = node->As<glsl::PrecisionDeclaration>();
      if (precision != nullptr && precision->type != nullptr) {
        has_default.insert(precision->type->name.text);
      }
    }
    std::vector<std::string> missing;
    if (context.Settings().stage == rule::ShaderStage::kFragment &&
        !has_default.contains("float")) {
      missing.push_back("float");
    }
    // shadertoy.com compiles every pass with `precision highp int;`: without it
    // int arithmetic would run at mediump in the port and change the picture.
    const rule::HarnessDialect* harness = context.Settings().harness;
    if (context.Settings().stage == rule::ShaderStage::kFragment && harness != nullptr &&
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

const rule::Rule& Webgl2PrecisionRule() {
  static const PrecisionRule rule;
  return rule;
}

}  // namespace shaderport::rules
