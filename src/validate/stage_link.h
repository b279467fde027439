// Links a vertex and a fragment shader with glslang, as a browser links a
// WebGL program: it checks that the stages agree on their interface.
#pragma once

#include <string>
#include <string_view>

namespace shaderport::validate {

struct StageLinkResult {
  bool compiled = false;  // both stages compiled (a link is only tried then)
  bool linked = false;
  std::string log;  // glslang's compile and link messages
};

// Both texts are whole shaders (with their #version). Thread-safe.
StageLinkResult LinkStages(std::string_view vertex, std::string_view fragment);

}  // namespace shaderport::validate
