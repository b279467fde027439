// Proves each external shader library is linked and callable, and reports what
// it found; `shaderport version` prints this.
#pragma once

#include <string>

namespace shaderport::toolchain {

struct ToolchainReport {
  std::string glslang_version;
  size_t spirv_words = 0;       // SPIR-V words glslang produced for a tiny shader
  bool spirv_valid = false;     // SPIRV-Tools' validator accepted them
  std::string cross_compiled;   // SPIRV-Cross turned them back into ESSL 3.00
  std::string osmesa_renderer;  // GL_RENDERER of an OSMesa context ("" if none)
  std::string osmesa_version;   // GL_VERSION of that context
  std::string error;            // first failure, if any step failed
};

ToolchainReport ProbeToolchain();

}  // namespace shaderport::toolchain
