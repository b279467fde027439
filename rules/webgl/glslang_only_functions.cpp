#include "rules/webgl/glslang_only_functions.h"

#include <algorithm>
#include <array>

namespace shaderport::rules::webgl {
namespace {

struct GlslangOnlyFunction {
  std::string_view name;
  std::string_view origin;
};

constexpr std::string_view kIntel = "GL_INTEL_shader_integer_functions2";
constexpr std::string_view kLod = "GL_EXT_shader_texture_lod";

// GLSL ES 3.00: glslang declares these whatever the shader enables.
constexpr std::array<GlslangOnlyFunction, 24> kEs3 = {{
    {"absoluteDifference", kIntel},
    {"addSaturate", kIntel},
    {"average", kIntel},
    {"averageRounded", kIntel},
    {"beginInvocationInterlockARB", "GL_ARB_fragment_shader_interlock"},
    {"controlBarrier", "GL_KHR_memory_scope_semantics"},
    {"countLeadingZeros", kIntel},
    {"countTrailingZeros", kIntel},
    {"debugPrintfEXT", "GL_EXT_debug_printf"},
    {"endInvocationInterlockARB", "GL_ARB_fragment_shader_interlock"},
    {"helperInvocationEXT", "GL_EXT_demote_to_helper_invocation"},
    {"imageLoad", "GLSL ES 3.10"},
    {"imageStore", "GLSL ES 3.10"},
    {"memoryBarrier", "GLSL ES 3.10"},
    {"multiply32x16", kIntel},
    {"shadow2DEXT", "GL_EXT_shadow_samplers"},
    {"shadow2DProjEXT", "GL_EXT_shadow_samplers"},
    {"subtractSaturate", kIntel},
    {"texture2DGradEXT", kLod},
    {"texture2DLodEXT", kLod},
    {"texture2DProjGradEXT", kLod},
    {"texture2DProjLodEXT", kLod},
    {"textureCubeGradEXT", kLod},
    {"textureCubeLodEXT", kLod},
}};

// GLSL ES 1.00: the derivatives, which browsers have only with their extension enabled.
constexpr std::array<GlslangOnlyFunction, 4> kEs1 = {{
    {"dFdx", "GL_OES_standard_derivatives"},
    {"dFdy", "GL_OES_standard_derivatives"},
    {"fwidth", "GL_OES_standard_derivatives"},
    {"debugPrintfEXT", "GL_EXT_debug_printf"},
}};

template <size_t N>
const GlslangOnlyFunction* Find(const std::array<GlslangOnlyFunction, N>& table,
                                std::string_view name) {
  const auto found =
      std::find_if(table.begin(), table.end(),
                   [&](const GlslangOnlyFunction& entry) { return entry.name == name; });
  return found == table.end() ? nullptr : &*found;
}

bool Enables(const glsl::PreprocessResult* preprocessed, std::string_view extension) {
  if (preprocessed == nullptr) return false;
  return std::any_of(preprocessed->extensions.begin(), preprocessed->extensions.end(),
                     [&](const glsl::ExtensionDirective& directive) {
                       return directive.name == extension && directive.behavior != "disable";
                     });
}

}  // namespace

bool IsGlslangOnlyFunction(std::string_view name, int version,
                           const glsl::PreprocessResult* preprocessed) {
  if (version >= 300) return Find(kEs3, name) != nullptr;
  const GlslangOnlyFunction* found = Find(kEs1, name);
  return found != nullptr && !Enables(preprocessed, found->origin);
}

std::string_view GlslangOnlyFunctionOrigin(std::string_view name) {
  if (const GlslangOnlyFunction* found = Find(kEs3, name)) return found->origin;
  if (const GlslangOnlyFunction* found = Find(kEs1, name)) return found->origin;
  return {};
}

}  // namespace shaderport::rules::webgl
