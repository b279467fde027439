// The site's header (uniforms, precision, sampler type per channel, HW_PERFORMANCE)
// and main() follow shadertoy.com as documented in design notes §1c. Deliberate
// differences, none of which changes what compiles:
// - The entry-point prototype comes AFTER the user's code, not before it: with the
//   user's `precision mediump float;` glslang otherwise reports a false "overloaded
//   functions must have the same parameter precision qualifiers" (browsers accept it).
// - Names the generated code uses are prefixed `shadertoy_` and prototypes have no
//   parameter names, so that a user macro such as `#define color ...` cannot rewrite
//   the generated main(). When the user defines the entry point itself as a macro
//   (`#define mainImage(c, p) ...`, seen in the corpus), the prototype is skipped and
//   main() calls the macro, as it does on the site where the prototype comes first.
// - The output variable and the cube/sound uniforms are declared in the header, so
//   that a user declaration clashing with them is reported on the user's line.
#include "validate/shadertoy_contract.h"

#include <algorithm>

#include "model/shipped_dialects.h"

namespace shaderport::validate {
namespace {

// `uniform vec3 iResolution;`: the site leaves precision to the header's defaults.
std::string SiteDeclaration(const model::ProvidedVariable& variable,
                            std::string_view type_override = {}) {
  return model::DeclarationOf(variable, type_override, model::PrecisionSpelling::kOmitted) + "\n";
}

}  // namespace

std::string_view EntryPointName(model::PassKind type) {
  if (type == model::PassKind::kCube) return "mainCubemap";
  if (type == model::PassKind::kSound) return "mainSound";
  return "mainImage";
}

std::string_view EntryPointSignature(model::PassKind type) {
  if (type == model::PassKind::kCube) {
    return "void mainCubemap(out vec4 fragColor, in vec2 fragCoord, in vec3 rayOri, in vec3 "
           "rayDir)";
  }
  if (type == model::PassKind::kSound) return "vec2 mainSound(int samp, float time)";
  return "void mainImage(out vec4 fragColor, in vec2 fragCoord)";
}

std::string ShaderToyHeader(model::PassKind type, const model::ChannelKinds& channels) {
  std::string header =
      "#version 300 es\n"
      "#ifdef GL_ES\n"
      "precision highp float;\n"
      "precision highp int;\n"
      "precision mediump sampler3D;\n"
      "#endif\n";
  const model::HarnessDialect& site = model::ShaderToyDialect();
  if (type == model::PassKind::kCommon) {
    // The site compiles the Common tab on its own behind a shorter header: only the
    // uniforms the TOML marks in_common_tab, no channels, no HW_PERFORMANCE. Shaders
    // test for it (`#ifndef HW_PERFORMANCE`, `#if __LINE__ < 17`) and declare what
    // they need.
    for (const model::ProvidedVariable* uniform : model::ShaderToySiteUniforms()) {
      if (uniform->in_common_tab) header += SiteDeclaration(*uniform);
    }
    return header + "out vec4 shadertoy_out_color;\n";
  }
  // The uniforms, then the channels with the sampler type each is bound as, then
  // what the pass's entry point adds: all as rules/dialects/shadertoy.toml lists them.
  for (const model::ProvidedVariable* uniform : model::ShaderToySiteUniforms()) {
    header += SiteDeclaration(*uniform);
  }
  for (const model::ProvidedVariable& variable : site.provides) {
    if (variable.channel < 0) continue;
    header += SiteDeclaration(
        variable, model::SamplerTypeName(channels[static_cast<size_t>(variable.channel)]));
  }
  if (const model::EntryPoint* entry = site.FindEntryPoint(EntryPointName(type))) {
    for (const model::ProvidedVariable& variable : entry->provides) {
      header += SiteDeclaration(variable);
    }
  }
  header += "out vec4 shadertoy_out_color;\n";
  for (const std::string& define : site.defines) header += "#define " + define + "\n";
  return header;
}

std::string ShaderToyEpilogue(model::PassKind type) {
  switch (type) {
    case model::PassKind::kSound:
      return "#ifndef mainSound\n"
             "vec2 mainSound(int, float);\n"
             "#endif\n"
             "void main() {\n"
             "  float shadertoy_t = iTimeOffset + ((gl_FragCoord.x - 0.5) + "
             "(gl_FragCoord.y - 0.5) * 512.0) / iSampleRate;\n"
             "  int shadertoy_s = iSampleOffset + int(gl_FragCoord.y - 0.2) * 512 + "
             "int(gl_FragCoord.x - 0.2);\n"
             "  vec2 shadertoy_y = mainSound(shadertoy_s, shadertoy_t);\n"
             "  vec2 shadertoy_v = floor((0.5 + 0.5 * shadertoy_y) * 65536.0);\n"
             "  vec2 shadertoy_vl = mod(shadertoy_v, 256.0) / 255.0;\n"
             "  vec2 shadertoy_vh = floor(shadertoy_v / 256.0) / 255.0;\n"
             "  shadertoy_out_color = vec4(shadertoy_vl.x, shadertoy_vh.x, shadertoy_vl.y, "
             "shadertoy_vh.y);\n"
             "}\n";
    case model::PassKind::kCube:
      return "#ifndef mainCubemap\n"
             "void mainCubemap(out vec4, in vec2, in vec3, in vec3);\n"
             "#endif\n"
             "void main() {\n"
             "  vec4 shadertoy_color = vec4(1e20);\n"
             "  vec3 shadertoy_ro = unCorners[4];\n"
             "  vec2 shadertoy_uv = (gl_FragCoord.xy - unViewport.xy) / unViewport.zw;\n"
             "  vec3 shadertoy_rd = normalize(mix(mix(unCorners[0], unCorners[1], shadertoy_uv.x), "
             "mix(unCorners[3], unCorners[2], shadertoy_uv.x), shadertoy_uv.y) - shadertoy_ro);\n"
             "  mainCubemap(shadertoy_color, gl_FragCoord.xy - unViewport.xy, shadertoy_ro, "
             "shadertoy_rd);\n"
             "  shadertoy_out_color = shadertoy_color;\n"
             "}\n";
    case model::PassKind::kCommon:
      return "void main() {\n"
             "  shadertoy_out_color = vec4(0.0);\n"
             "}\n";
    case model::PassKind::kImage:
    case model::PassKind::kBuffer:
      break;
  }
  std::string epilogue =
      "#ifndef mainImage\n"
      "void mainImage(out vec4, in vec2);\n"
      "#endif\n"
      "void main() {\n"
      "  vec4 shadertoy_color = vec4(1e20);\n"
      "  mainImage(shadertoy_color, gl_FragCoord.xy);\n";
  // Image forces alpha to 1; buffers keep what the shader wrote.
  epilogue += type != model::PassKind::kBuffer
                  ? "  shadertoy_out_color = vec4(shadertoy_color.xyz, 1.0);\n"
                  : "  shadertoy_out_color = shadertoy_color;\n";
  epilogue += "}\n";
  return epilogue;
}

namespace {

// A part whose last line has no newline, or ends in a line continuation, is followed
// by a newline of its own (see ComposeShaderToyRequest).
bool NeedsSeparator(std::string_view text) {
  const bool continued = text.ends_with("\\\n") || text.ends_with("\\\r\n");
  return (!text.empty() && text.back() != '\n' && text.back() != '\r') || continued;
}

}  // namespace

std::vector<int64_t> ShaderToyFirstLines(model::PassKind type, const SourceFile* common) {
  const auto lines = [](std::string_view text) {
    return static_cast<int64_t>(std::count(text.begin(), text.end(), '\n'));
  };
  std::vector<int64_t> first{lines(ShaderToyHeader(type, model::ChannelKinds{})) + 1};
  if (common != nullptr) {
    first.push_back(first.back() + lines(common->Text()) +
                    (NeedsSeparator(common->Text()) ? 1 : 0));
  }
  return first;
}

ValidationRequest ComposeShaderToyRequest(SourceManager& sources, model::PassKind type,
                                          const model::ChannelKinds& channels,
                                          const SourceFile* common, const SourceFile& pass) {
  ValidationRequest request;
  request.stage = model::Stage::kFragment;
  request.default_version = 300;
  request.link = true;
  request.entry_point = std::string(EntryPointName(type));
  request.entry_point_signature = std::string(EntryPointSignature(type));
  auto add_generated = [&](std::string name, std::string text) {
    const SourceFile& file = sources.Add(name, std::move(text), /*synthetic=*/true);
    request.parts.push_back({std::move(name), file.Text(), file.Id(), PartKind::kGenerated});
  };
  // Strings are concatenated: a part whose last line has no newline, or ends in a
  // line continuation ('\' before the newline), would run into the next part's
  // first line (a '#ifndef' there would stop being a directive), so a newline is
  // added between them, which the continuation then joins harmlessly.
  auto add_user = [&](const SourceFile& file) {
    request.parts.push_back({file.Name(), file.Text(), file.Id(), PartKind::kUser});
    if (NeedsSeparator(file.Text())) add_generated("shadertoy-separator", "\n");
  };
  add_generated("shadertoy-header", ShaderToyHeader(type, channels));
  if (common != nullptr) add_user(*common);
  add_user(pass);
  add_generated("shadertoy-epilogue", ShaderToyEpilogue(type));
  return request;
}

}  // namespace shaderport::validate
