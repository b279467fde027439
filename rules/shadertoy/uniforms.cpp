// shadertoy/uniforms: declares what the harness provides (ShaderToy's uniforms,
// exactly as the site declares them, with each channel's sampler type; a dialect
// file's uniforms, inputs and outputs) and its #defines, after the #version line.
//
// Before:                                  After:
//   #version 300 es                          #version 300 es
//   void mainImage(out vec4 c, in vec2 p) {  uniform highp vec3 iResolution;
//     c = vec4(p / iResolution.xy, 0, 1);    uniform highp float iTime;
//   }                                        ... (every uniform of the site)
//                                            uniform sampler2D iChannel0;
//                                            ...
//                                            #define HW_PERFORMANCE 1
//                                            void mainImage(out vec4 c, in vec2 p) {
//
// Declarations carry their precision (highp, as the hosts' defaults) so that they
// are valid wherever port/precision puts its statement. Without a #version the
// rule waits a round for port/version, which inserts at offset 0.
#include <algorithm>
#include <iterator>
#include <set>
#include <string>

#include "rules/all_rules.h"
#include "rules/shadertoy/harness_support.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "shadertoy/uniforms";

// GLSL ES 1.00 words the port itself rewrites for GLSL ES 3.00 (port/interface,
// port/frag-outputs, port/texture-functions). A host that compiles 1.00-style code as
// 3.00 (three.js) maps them with #define; WebGL2 output needs no such define, nor the
// output a define of gl_FragColor names.
bool PortRewrites(std::string_view word) {
  static constexpr std::string_view kWords[] = {
      "attribute", "varying", "gl_FragColor", "gl_FragData", "gl_FragDepthEXT",
#define TEXTURE_RENAME(from, to) #from,
#include "rules/data/webgl2_texture_renames.def"
#undef TEXTURE_RENAME
  };
  return std::find(std::begin(kWords), std::end(kWords), word) != std::end(kWords);
}

// The outputs that a #define of a rewritten word names (`gl_FragColor pc_fragColor`).
std::set<std::string, std::less<>> OutputsBehindRewrites(const model::HarnessDialect& dialect) {
  std::set<std::string, std::less<>> outputs;
  for (const std::string& define : dialect.defines) {
    const size_t space = define.find(' ');
    if (space == std::string::npos || !PortRewrites(define.substr(0, space))) continue;
    outputs.insert(define.substr(space + 1));
  }
  return outputs;
}

class UniformsRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{
        kId, "Declare the uniforms, inputs and defines the harness provides",
        "void mainImage(out vec4 c, in vec2 p) { c = vec4(p / iResolution.xy, 0, 1); }",
        "uniform highp vec3 iResolution;\nuniform highp float iTime;\n...\n"
        "#define HW_PERFORMANCE 1\n"
        "void mainImage(out vec4 c, in vec2 p) { c = vec4(p / iResolution.xy, 0, 1); }",
        rule::RuleScope::kPort};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    const model::HarnessDialect* dialect = context.Settings().harness;
    if (dialect == nullptr || context.Settings().stage != model::Stage::kFragment) return;
    const std::optional<uint32_t> offset = harness::AfterVersionLines(context);
    if (!offset) return;  // port/version adds the #version first
    const rule::CodeInterface code = rule::ReadCodeInterface(context.Tree(), context.Model());
    const auto channels = harness::ChooseChannels(context, *dialect);

    std::vector<const model::ProvidedVariable*> provided;
    for (const model::ProvidedVariable& variable : dialect->provides) provided.push_back(&variable);
    if (const model::EntryPoint* entry = harness::DefinedEntryPoint(*dialect, code)) {
      for (const model::ProvidedVariable& variable : entry->provides) provided.push_back(&variable);
    }
    std::string text;
    std::string names;
    const auto behind_rewrites = OutputsBehindRewrites(*dialect);
    for (const model::ProvidedVariable* variable : provided) {
      // The code's own declaration wins (and a second one would not compile).
      if (code.globals.contains(variable->name) || code.functions.contains(variable->name)) {
        continue;
      }
      if (behind_rewrites.contains(variable->name) &&
          !code.free_identifiers.contains(variable->name)) {
        continue;
      }
      if (dialect->declare == model::DeclareMode::kUsed &&
          !code.free_identifiers.contains(variable->name)) {
        continue;
      }
      text += model::DeclarationOf(*variable, harness::TypeFor(*variable, channels)) + "\n";
      names += (names.empty() ? "" : ", ") + variable->name;
    }
    const auto macros = harness::DefinedMacros(context);
    for (const std::string& define : dialect->defines) {
      const std::string name = define.substr(0, define.find(' '));
      if (macros.contains(name) || PortRewrites(name)) continue;
      text += "#define " + define + "\n";
      names += (names.empty() ? "" : ", ") + name;
    }
    if (text.empty()) return;

    Diagnostic diagnostic;
    diagnostic.severity = Severity::kWarning;
    diagnostic.rule_id = std::string(kId);
    diagnostic.range = {context.File().Id(), *offset, *offset};
    diagnostic.message = "the " + dialect->name + " harness provides " + names +
                         "; WebGL2 code must declare them: adding the declarations";
    diagnostic.fixes.push_back(
        FixIt{{context.File().Id(), *offset, *offset}, std::move(text), FixSafety::kSafe});
    // Say why a channel is not a sampler2D (shadertoy/channel-types has the details).
    for (const model::ProvidedVariable* variable : provided) {
      if (variable->channel < 0 || code.globals.contains(variable->name)) continue;
      const harness::ChannelChoice& choice = channels[variable->channel];
      if (choice.type == "sampler2D") continue;
      diagnostic.notes.push_back(
          {choice.told || choice.use.first_cube == glsl::kNoNode
               ? SourceRange{}
               : context.Tree().NodeAt(choice.use.first_cube).range,
           variable->name + " is declared " + choice.type +
               (choice.told ? " as told" : ": the code samples it with 3-component coordinates")});
    }
    context.Report(std::move(diagnostic));
  }
};

}  // namespace

const rule::Rule& ShadertoyUniformsRule() {
  static const UniformsRule rule;
  return rule;
}

}  // namespace shaderport::rules
