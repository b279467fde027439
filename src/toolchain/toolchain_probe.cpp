#include "toolchain/toolchain_probe.h"

#include <GL/gl.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <exception>
#include <spirv-tools/libspirv.hpp>
#include <spirv_glsl.hpp>
#include <string>
#include <vector>

#include "base/osmesa_library.h"

namespace shaderport::toolchain {
namespace {

constexpr const char* kProbeShader =
    "#version 310 es\n"
    "precision highp float;\n"
    "layout(location = 0) out vec4 color;\n"
    "void main() { color = vec4(0.25, 0.5, 0.75, 1.0); }\n";

bool CompileProbe(std::vector<uint32_t>& spirv, std::string& error) {
  glslang::InitializeProcess();
  glslang::TShader shader(EShLangFragment);
  shader.setStrings(&kProbeShader, 1);
  shader.setEnvInput(glslang::EShSourceGlsl, EShLangFragment, glslang::EShClientOpenGL, 100);
  shader.setEnvClient(glslang::EShClientOpenGL, glslang::EShTargetOpenGL_450);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
  if (!shader.parse(GetDefaultResources(), 310, false, EShMsgSpvRules)) {
    error = shader.getInfoLog();
    return false;
  }
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(EShMsgSpvRules)) {
    error = program.getInfoLog();
    return false;
  }
  glslang::GlslangToSpv(*program.getIntermediate(EShLangFragment), spirv);
  return true;
}

void ProbeOsMesa(ToolchainReport& report) {
  std::string load_error;
  const OsMesaLibrary* lib = LoadOsMesa(load_error);
  if (lib == nullptr) {
    if (report.error.empty()) report.error = "OSMesa: " + load_error;
    return;
  }
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            3,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            3,
                            0};
  OSMesaContext context = lib->create_context_attribs(attributes, nullptr);
  if (context == nullptr) {
    if (report.error.empty()) report.error = "OSMesa: context creation failed";
    return;
  }
  std::vector<unsigned char> pixels(4 * 4 * 4);
  if (lib->make_current(context, pixels.data(), GL_UNSIGNED_BYTE, 4, 4) != 0) {
    using GetStringFn = const GLubyte* (*)(GLenum);
    const auto get_string = reinterpret_cast<GetStringFn>(lib->get_proc_address("glGetString"));
    const auto* renderer =
        get_string ? reinterpret_cast<const char*>(get_string(GL_RENDERER)) : nullptr;
    const auto* version =
        get_string ? reinterpret_cast<const char*>(get_string(GL_VERSION)) : nullptr;
    report.osmesa_renderer = renderer != nullptr ? renderer : "";
    report.osmesa_version = version != nullptr ? version : "";
    lib->make_current(nullptr, nullptr, 0, 0, 0);
  } else {
    if (report.error.empty()) report.error = "OSMesa: make current failed";
  }
  lib->destroy_context(context);
}

}  // namespace

ToolchainReport ProbeToolchain() {
  ToolchainReport report;
  report.glslang_version = std::to_string(glslang::GetVersion().major) + "." +
                           std::to_string(glslang::GetVersion().minor) + "." +
                           std::to_string(glslang::GetVersion().patch);
  std::vector<uint32_t> spirv;
  if (!CompileProbe(spirv, report.error)) return report;
  report.spirv_words = spirv.size();

  spvtools::SpirvTools tools(SPV_ENV_OPENGL_4_5);
  report.spirv_valid = tools.Validate(spirv);
  if (!report.spirv_valid) report.error = "SPIRV-Tools: the probe module did not validate";

  // SPIRV-Cross reports failures by throwing; the library must not let them escape.
  try {
    spirv_cross::CompilerGLSL cross(spirv);
    spirv_cross::CompilerGLSL::Options options;
    options.es = true;
    options.version = 300;
    cross.set_common_options(options);
    report.cross_compiled = cross.compile();
  } catch (const std::exception& e) {
    if (report.error.empty()) report.error = std::string("SPIRV-Cross: ") + e.what();
  }

  ProbeOsMesa(report);
  return report;
}

}  // namespace shaderport::toolchain
