#include "toolchain/spirv_compile.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <mutex>
#include <string>

#include "toolchain/glslang_log.h"

namespace shaderport::toolchain {
namespace {

constexpr const char* kLegPrefix =
    "the SPIR-V leg (glslang, forced to 310 es) cannot compile this valid WebGL2 shader: ";

void InitializeGlslangOnce() {
  static std::once_flag once;
  std::call_once(once, [] { glslang::InitializeProcess(); });
}

EShLanguage Language(model::Stage stage) {
  return stage == model::Stage::kVertex ? EShLangVertex : EShLangFragment;
}

void SetSource(glslang::TShader& shader, const SourceFile& file, const char*& text, int& length) {
  text = file.Text().data();
  length = static_cast<int>(file.Text().size());
  shader.setStringsWithLengths(&text, &length, 1);
}

// The authoritative question: is the text valid GLSL ES 3.00 (pure validation, as `check`)?
// Returns glslang's log when it is not, "" when it is.
std::string EsslErrors(const SourceFile& file, model::Stage stage) {
  glslang::TShader shader(Language(stage));
  const char* text = nullptr;
  int length = 0;
  SetSource(shader, file, text, length);
  shader.setEnvInput(glslang::EShSourceGlsl, Language(stage), glslang::EShClientNone, 0);
  shader.setEnvClient(glslang::EShClientNone, static_cast<glslang::EShTargetClientVersion>(0));
  shader.setEnvTarget(glslang::EShTargetNone, static_cast<glslang::EShTargetLanguageVersion>(0));
  if (!shader.parse(GetDefaultResources(), 100, false, EShMsgCascadingErrors)) {
    return shader.getInfoLog();
  }
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(EShMsgDefault)) return program.getInfoLog();
  return "";
}

// The leg failed: decide whose fault it is, and say so.
void ReportFailure(const std::string& leg_log, const SourceFile& file, model::Stage stage,
                   DiagnosticList& out) {
  const std::string essl_log = EsslErrors(file, stage);
  if (!essl_log.empty()) {
    AppendGlslangErrors(essl_log, file, "spirv/invalid-input", Severity::kError,
                        "not a valid ESSL 3.00 shader: ", out);
    return;
  }
  AppendGlslangErrors(leg_log, file, "spirv/leg-limitation", Severity::kError, kLegPrefix, out);
}

}  // namespace

SpirvCompilation CompileToSpirv(const SourceFile& file, model::Stage stage) {
  InitializeGlslangOnce();
  SpirvCompilation result;
  const EShLanguage language = Language(stage);
  const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgCascadingErrors);
  glslang::TShader shader(language);
  const char* text = nullptr;
  int length = 0;
  SetSource(shader, file, text, length);
  shader.setEnvInput(glslang::EShSourceGlsl, language, glslang::EShClientOpenGL, 100);
  shader.setEnvClient(glslang::EShClientOpenGL, glslang::EShTargetOpenGL_450);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
  shader.setAutoMapLocations(true);
  shader.setAutoMapBindings(true);
  // Forcing the version (rather than editing the #version line) keeps every line number.
  if (!shader.parse(GetDefaultResources(), 310, EEsProfile, /*force=*/true, false, messages)) {
    ReportFailure(shader.getInfoLog(), file, stage, result.diagnostics);
    return result;
  }
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages) || !program.mapIO()) {
    ReportFailure(program.getInfoLog(), file, stage, result.diagnostics);
    return result;
  }
  glslang::SpvOptions options;
  options.disableOptimizer = true;  // spirv_tools.h optimises on request, and counts words
  options.validate = false;         // spirv_tools.h validates, with diagnostics
  spv::SpvBuildLogger logger;
  glslang::GlslangToSpv(*program.getIntermediate(language), result.words, &logger, &options);
  if (result.words.empty()) {
    result.diagnostics.push_back(
        {Severity::kError,
         "spirv/leg-limitation",
         {file.Id(), 0, 0},
         std::string(kLegPrefix) + "glslang produced no SPIR-V. " + logger.getAllMessages(),
         {},
         {}});
  }
  return result;
}

}  // namespace shaderport::toolchain
