#include "validate/stage_link.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include "base/large_stack.h"
#include "validate/glslang_runner.h"

namespace shaderport::validate {
namespace {

bool Compile(glslang::TShader& shader, EShLanguage language, std::string_view text,
             std::string& log) {
  const char* data = text.data();
  const int length = static_cast<int>(text.size());
  shader.setStringsWithLengths(&data, &length, 1);
  shader.setEnvInput(glslang::EShSourceGlsl, language, glslang::EShClientNone, 0);
  shader.setEnvClient(glslang::EShClientNone, static_cast<glslang::EShTargetClientVersion>(0));
  shader.setEnvTarget(glslang::EShTargetNone, static_cast<glslang::EShTargetLanguageVersion>(0));
  const bool ok = shader.parse(GetDefaultResources(), 100, false,
                               static_cast<EShMessages>(EShMsgCascadingErrors));
  log += shader.getInfoLog();
  return ok;
}

}  // namespace

StageLinkResult LinkStages(std::string_view vertex, std::string_view fragment) {
  InitializeGlslangOnce();
  StageLinkResult result;
  // glslang's pool allocator is per thread, and deep input recurses: run on a
  // thread of our own with a large stack, as single-stage validation does.
  RunOnLargeStack([&] {
    glslang::TShader vertex_shader(EShLangVertex);
    glslang::TShader fragment_shader(EShLangFragment);
    const bool vertex_ok = Compile(vertex_shader, EShLangVertex, vertex, result.log);
    const bool fragment_ok = Compile(fragment_shader, EShLangFragment, fragment, result.log);
    result.compiled = vertex_ok && fragment_ok;
    if (!result.compiled) return;
    glslang::TProgram program;
    program.addShader(&vertex_shader);
    program.addShader(&fragment_shader);
    result.linked = program.link(static_cast<EShMessages>(EShMsgCascadingErrors));
    result.log += program.getInfoLog();
  });
  return result;
}

}  // namespace shaderport::validate
