// Takes a port's WebGL2 result on through the SPIR-V leg (`port --emit`).
#pragma once

#include <string>

#include "driver/port/port_file.h"
#include "toolchain/emit.h"

namespace shaderport::driver {

struct EmittedOutput {
  std::string output;       // what to write: text or SPIR-V bytes; empty on errors
  std::string extension;    // ".spv", ".hlsl", ... for --out-dir names
  size_t words_before = 0;  // SPIR-V words, for the optimiser's report
  size_t words_after = 0;
};

// Emits `result.text` as `options.kind`. The ported text is registered in
// `sources` as a synthetic file; diagnostics the leg raises are appended to
// `result.diagnostics`, mapped back to the user's original file where the
// ported text was copied from it.
EmittedOutput EmitPorted(PortResult& result, const toolchain::EmitOptions& options,
                         SourceManager& sources);

}  // namespace shaderport::driver
