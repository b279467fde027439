// In-process glslang compile used by the sema tests as the reference front end.
#pragma once

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <string>

#include "glsl/sema/language.h"

namespace shaderport::glsl::testing {

struct GlslangResult {
  bool ok = false;
  std::string log;
};

// Parses one shader (no link). `source` carries its own #version line, if any.
inline GlslangResult CompileWithGlslang(const std::string& source, model::Stage stage) {
  static const bool initialized = glslang::InitializeProcess();
  (void)initialized;
  EShLanguage language = stage == model::Stage::kVertex ? EShLangVertex : EShLangFragment;
  glslang::TShader shader(language);
  const char* text = source.c_str();
  shader.setStrings(&text, 1);
  shader.setEnvInput(glslang::EShSourceGlsl, language, glslang::EShClientNone, 0);
  shader.setEnvClient(glslang::EShClientNone, static_cast<glslang::EShTargetClientVersion>(0));
  shader.setEnvTarget(glslang::EShTargetNone, static_cast<glslang::EShTargetLanguageVersion>(0));
  GlslangResult result;
  result.ok = shader.parse(GetDefaultResources(), 100, false, EShMsgDefault);
  result.log = shader.getInfoLog();
  return result;
}

}  // namespace shaderport::glsl::testing
