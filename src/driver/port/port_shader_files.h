// The `port` of shader files that are not ShaderToy projects (port_run.h): each
// file ported on its own, in parallel, then linked with its other stage and taken
// on through the SPIR-V leg.
#pragma once

#include <vector>

#include "driver/input_files.h"
#include "driver/port/port_run.h"
#include "source/source_manager.h"

namespace shaderport::driver {

// Ports `inputs` into `run`: their findings, where each output goes, and the
// outputs written (or kept for standard output) unless two would collide.
void PortShaderFiles(const std::vector<InputFile>& inputs, const PortRunOptions& options,
                     SourceManager& sources, PortRun& run);

}  // namespace shaderport::driver
