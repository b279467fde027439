// Test helpers for the SPIR-V leg: corpus files as whole WebGL2 shaders, glslang validation
// of generated ESSL, and running spirv-val on a module.
#pragma once

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "scratch_dir.h"
#include "toolchain/emit.h"

namespace shaderport::toolchain::testing {

namespace fs = std::filesystem;

inline std::string ReadText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

inline void WriteText(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

// shadertoy.com's WebGL2 page header and epilogue, as corpus_manifest_test.cpp and
// src/validate/shadertoy_contract.cpp compose them (all four channels 2D).
inline constexpr const char* kShaderToyHeader =
    "#version 300 es\n"
    "precision highp float;\nprecision highp int;\nprecision mediump sampler3D;\n"
    "#define HW_PERFORMANCE 1\n"
    "uniform vec3 iResolution;\nuniform float iTime;\nuniform float iChannelTime[4];\n"
    "uniform vec4 iMouse;\nuniform vec4 iDate;\nuniform float iSampleRate;\n"
    "uniform vec3 iChannelResolution[4];\nuniform int iFrame;\nuniform float iTimeDelta;\n"
    "uniform float iFrameRate;\nuniform sampler2D iChannel0;\nuniform sampler2D iChannel1;\n"
    "uniform sampler2D iChannel2;\nuniform sampler2D iChannel3;\n"
    "void mainImage(out vec4 c, in vec2 f);\n";
inline constexpr const char* kShaderToyFooter =
    "\nout vec4 shadertoy_out_color;\n"
    "void main() {\n  vec4 color = vec4(1e20);\n  mainImage(color, gl_FragCoord.xy);\n"
    "  shadertoy_out_color = vec4(color.xyz, 1.0);\n}\n";
inline constexpr const char* kHarnessHeader =
    "#version 300 es\nprecision highp float;\nin vec2 uv;\nuniform float time;\n"
    "out vec4 color;\n";

// A mechanical WebGL1 -> WebGL2 port, enough for the corpus's ssao files until
// `shaderport port` exists: version line, attribute/varying, texture2D, gl_FragColor.
inline std::string PortWebGl1(const std::string& text, model::Stage stage) {
  std::string out = std::regex_replace(text, std::regex(R"(\battribute\b)"), "in");
  out = std::regex_replace(out, std::regex(R"(\bvarying\b)"),
                           stage == model::Stage::kVertex ? "out" : "in");
  out = std::regex_replace(out, std::regex(R"(\btexture(2D|Cube)\s*\()"), "texture(");
  out = std::regex_replace(out, std::regex(R"(\bgl_FragColor\b)"), "port_FragColor");
  std::string header = "#version 300 es\n";
  if (stage == model::Stage::kFragment)
    header += "precision highp float;\nout vec4 port_FragColor;\n";
  return header + out;
}

struct CorpusShader {
  std::string path;  // relative to corpus/
  model::Stage stage = model::Stage::kFragment;
  bool shadertoy = false;
  std::string webgl2;  // a whole WebGL2 shader
};

// Every corpus file whose MANIFEST row says it compiles, as WebGL2 text.
inline std::vector<CorpusShader> CompilingCorpusShaders() {
  const fs::path corpus = fs::path(SHADERPORT_SOURCE_DIR) / "corpus";
  std::istringstream manifest(ReadText(corpus / "MANIFEST"));
  std::vector<CorpusShader> shaders;
  std::string line;
  std::getline(manifest, line);  // header
  while (std::getline(manifest, line)) {
    std::vector<std::string> f;
    std::istringstream fields(line);
    for (std::string field; std::getline(fields, field, '\t');) f.push_back(field);
    if (f.size() != 5 || f[4] != "compiles") continue;
    CorpusShader shader{f[0], f[3] == "vertex" ? model::Stage::kVertex : model::Stage::kFragment,
                        f[2] == "shadertoy", ""};
    const std::string text = ReadText(corpus / f[0]);
    if (f[2] == "shadertoy") {
      shader.webgl2 = kShaderToyHeader + text + kShaderToyFooter;
    } else if (f[2] == "raymarch-harness") {
      shader.webgl2 = kHarnessHeader + text;
    } else if (f[2] == "webgl1") {
      shader.webgl2 = PortWebGl1(text, shader.stage);
    } else {
      shader.webgl2 = text;
    }
    shaders.push_back(std::move(shader));
  }
  return shaders;
}

// glslang's verdict on `text` as GLSL ES 3.00 (pure validation, as `check` runs it): "" when
// it compiles and links, else the log.
inline std::string GlslangErrors(const std::string& text, model::Stage stage) {
  glslang::InitializeProcess();
  const EShLanguage language = stage == model::Stage::kVertex ? EShLangVertex : EShLangFragment;
  glslang::TShader shader(language);
  const char* source = text.c_str();
  shader.setStrings(&source, 1);
  shader.setEnvInput(glslang::EShSourceGlsl, language, glslang::EShClientNone, 0);
  shader.setEnvClient(glslang::EShClientNone, static_cast<glslang::EShTargetClientVersion>(0));
  shader.setEnvTarget(glslang::EShTargetNone, static_cast<glslang::EShTargetLanguageVersion>(0));
  if (!shader.parse(GetDefaultResources(), 100, false, EShMsgCascadingErrors)) {
    return shader.getInfoLog();
  }
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(EShMsgDefault)) return std::string("link: ") + program.getInfoLog();
  return "";
}

// Runs the spirv-val command-line tool on a module; "" when it accepts it.
inline std::string SpirvValErrors(const std::string& bytes, const std::string& name) {
  const fs::path dir = shaderport::testing::ScratchRoot::Path() / "spirv";
  fs::create_directories(dir);
  std::string file_name = name;
  for (char& c : file_name) {
    if (c == '/') c = '_';
  }
  const fs::path module = dir / (file_name + ".spv");
  const fs::path log = dir / (file_name + ".log");
  WriteText(module, bytes);
  const std::string command =
      "spirv-val --target-env opengl4.5 '" + module.string() + "' > '" + log.string() + "' 2>&1";
  const int status = std::system(command.c_str());
  std::string output = ReadText(log);
  fs::remove(module);
  fs::remove(log);
  if (status == 0) return "";
  return output.empty() ? "spirv-val exited with " + std::to_string(status) : output;
}

inline std::string RuleIds(const DiagnosticList& diagnostics) {
  std::string ids;
  for (const Diagnostic& d : diagnostics) ids += d.rule_id + ": " + d.message + "\n";
  return ids;
}

inline EmitOptions OptionsFor(EmitKind kind) {
  EmitOptions options;
  options.kind = kind;
  return options;
}

inline EmitResult EmitText(const std::string& text, model::Stage stage, EmitOptions options,
                           const std::string& name = "test.frag") {
  const SourceFile file(0, name, text);
  return Emit(file, stage, options);
}

}  // namespace shaderport::toolchain::testing
