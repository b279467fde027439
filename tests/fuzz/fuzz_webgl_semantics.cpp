// libFuzzer target for the render transforms (glsl/webgl_semantics): for any bytes
// (behind a `#version 300 es` line unless they start with one) the transforms must
// not crash, must keep the number of lines, must hand back clean-parse failures
// unchanged, must give a source map the size of the text, and must never turn a
// shader glslang compiles into one it rejects.
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "base/limits.h"
#include "glsl/webgl_semantics/browser_semantics.h"
#include "source/source_manager.h"

namespace {

void Check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "fuzz_webgl_semantics: %s\n", what);
    std::abort();
  }
}

bool Compiles(const std::string& text) {
  static const bool initialized = glslang::InitializeProcess();
  (void)initialized;
  glslang::TShader shader(EShLangFragment);
  const char* source = text.c_str();
  shader.setStrings(&source, 1);
  shader.setEnvInput(glslang::EShSourceGlsl, EShLangFragment, glslang::EShClientNone, 0);
  shader.setEnvClient(glslang::EShClientNone, static_cast<glslang::EShTargetClientVersion>(0));
  shader.setEnvTarget(glslang::EShTargetNone, static_cast<glslang::EShTargetLanguageVersion>(0));
  return shader.parse(GetDefaultResources(), 300, false, EShMsgDefault);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace shaderport;
  // Kept small: every input is compiled by glslang up to twice.
  if (size > 16384) return 0;
  const std::string input(reinterpret_cast<const char*>(data), size);
  // A complete shader (e.g. a WebGL2 seed) is taken as it is; anything else gets the
  // header render puts in front of ShaderToy code's essentials.
  const std::string text =
      input.starts_with("#version") ? input : "#version 300 es\nprecision highp float;\n" + input;
  SourceManager sources;
  const SourceFile& file = sources.Add("fuzz.frag", text);
  const std::array<const SourceFile*, 1> parts = {&file};
  glsl::BrowserSemanticsOptions options;
  options.zero_out_parameters = true;
  options.add_render_probe = true;
  options.probe_in_alpha = size % 2 == 1;  // both places of the probe
  options.cpu_browser_math = true;         // as render applies them
  options.source_order_arithmetic = true;
  const glsl::BrowserSemanticsResult result = glsl::ApplyBrowserSemantics(parts, options);
  Check(result.texts.size() == 1 && result.maps.size() == 1, "one text and map per part");
  const std::string& edited = result.texts.front();
  Check(
      std::count(edited.begin(), edited.end(), '\n') == std::count(text.begin(), text.end(), '\n'),
      "line count changed");
  Check(result.maps.front().OutputSize() == edited.size(), "source map size");
  if (!result.applied) Check(edited == text, "unparsed text changed");
  if (edited != text && Compiles(text))
    Check(Compiles(edited), "transform broke a compiling shader");
  return 0;
}
