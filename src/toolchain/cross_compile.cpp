#include "toolchain/cross_compile.h"

#include <exception>
#include <memory>
#include <spirv_glsl.hpp>
#include <spirv_hlsl.hpp>
#include <spirv_msl.hpp>

namespace shaderport::toolchain {
namespace {

std::unique_ptr<spirv_cross::CompilerGLSL> MakeCompiler(const SpirvWords& words, CrossTarget target,
                                                        const CrossOptions& options) {
  switch (target) {
    case CrossTarget::kHlsl: {
      auto hlsl = std::make_unique<spirv_cross::CompilerHLSL>(words);
      spirv_cross::CompilerHLSL::Options hlsl_options;
      hlsl_options.shader_model = static_cast<uint32_t>(options.hlsl_shader_model);
      hlsl->set_hlsl_options(hlsl_options);
      return hlsl;
    }
    case CrossTarget::kMsl: {
      auto msl = std::make_unique<spirv_cross::CompilerMSL>(words);
      spirv_cross::CompilerMSL::Options msl_options;
      msl_options.msl_version = static_cast<uint32_t>(options.msl_version);
      msl->set_msl_options(msl_options);
      return msl;
    }
    case CrossTarget::kEssl300: {
      auto glsl = std::make_unique<spirv_cross::CompilerGLSL>(words);
      spirv_cross::CompilerGLSL::Options glsl_options;
      glsl_options.es = true;
      glsl_options.version = 300;
      glsl->set_common_options(glsl_options);
      return glsl;
    }
  }
  return nullptr;
}

}  // namespace

CrossOutcome CrossCompile(const SpirvWords& words, CrossTarget target,
                          const CrossOptions& options) {
  CrossOutcome outcome;
  try {
    std::unique_ptr<spirv_cross::CompilerGLSL> compiler = MakeCompiler(words, target, options);
    if (compiler == nullptr) {
      outcome.error = "unknown target";
      return outcome;
    }
    outcome.text = compiler->compile();
  } catch (const std::exception& e) {
    outcome.text.clear();
    outcome.error = e.what();
  } catch (...) {
    outcome.text.clear();
    outcome.error = "SPIRV-Cross failed with an unknown exception";
  }
  if (outcome.text.empty() && outcome.error.empty()) outcome.error = "SPIRV-Cross produced no text";
  return outcome;
}

}  // namespace shaderport::toolchain
