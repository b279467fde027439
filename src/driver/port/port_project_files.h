// The `port` of ShaderToy projects (JSON documents, .jsonl, project folders), and of
// any input made into a page or folder (port_run.h): a shader per pass under
// --out-dir, a page per project or per vertex and fragment pair, or the folder layout.
#pragma once

#include <vector>

#include "driver/input_files.h"
#include "driver/port/port_run.h"
#include "source/source_manager.h"

namespace shaderport::driver {

// Ports `inputs` into `run`: their findings, the outputs each document gives and
// where they go, written (or kept for standard output) unless they do not fit.
void PortProjectFiles(const std::vector<InputFile>& inputs, const PortRunOptions& options,
                      SourceManager& sources, PortRun& run);

}  // namespace shaderport::driver
