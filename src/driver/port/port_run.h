// `shaderport port` over the selected inputs (input_selection.h): shader files in
// parallel, linked by stage pairs and taken on through the SPIR-V leg, or ShaderToy
// projects and pages; the outputs named and written. The caller prints.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "driver/input_files.h"
#include "driver/port/port_file.h"
#include "source/source_manager.h"
#include "toolchain/emit.h"

namespace shaderport::driver {

// What a port writes for each input.
enum class PortLayout {
  kShaders,  // a shader per input (a project: per pass), through `emit`
  kPage,     // --emit html: a WebGL2 page per project, pass or vertex/fragment pair
  kFolder,   // --emit folder: the project folder layout, code as written
};

struct PortRunOptions {
  PortOptions port;  // --dialect, --channel, --stage (the mode is port's)
  PortLayout layout = PortLayout::kShaders;
  toolchain::EmitOptions emit;    // kShaders: ESSL, or on through the SPIR-V leg
  std::filesystem::path output;   // -o: the one target
  std::filesystem::path out_dir;  // --out-dir: each input's layout below it
  bool write_invalid = false;     // write outputs that do not compile too
  unsigned jobs = 0;              // files ported in parallel; 0: every core
  // Called as each shader file is done, one call at a time, from worker threads.
  std::function<void(size_t done, size_t total)> progress;
};

// SPIR-V words before and after the optimiser (--opt), for one written input.
struct OptimisedSize {
  std::filesystem::path input;
  size_t words_before = 0;
  size_t words_after = 0;
};

struct PortRun {
  // Inputs and targets that do not fit together (several files for one target,
  // two inputs on one output...): a usage error, and nothing was written.
  std::string usage_error;
  std::vector<PortResult> results;               // the findings, in input order
  std::string standard_output;                   // the outputs without a target (no -o, --out-dir)
  std::vector<OptimisedSize> optimised;          // --opt, in input order
  std::vector<std::string> write_errors;         // why a target could not be written
  std::vector<std::filesystem::path> unwritten;  // ported, but the output does not compile
  bool unsettled = false;  // some fixes did not settle: nothing of that input was written
};

// `inputs` as SelectConfiguredInputs gives them (`relative` below their common root
// is made here). The findings point into `sources`.
PortRun RunPort(std::vector<InputFile> inputs, const PortRunOptions& options,
                SourceManager& sources);

}  // namespace shaderport::driver
