// Porting a whole ShaderToy project: each pass becomes one complete WebGL2 fragment
// shader as the site would compile it (the site's uniforms, Common inlined, the
// pass's own main(): Buffers keep alpha, Image forces it to 1), findings located in
// the user's own pass or Common.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "driver/port/port_file.h"
#include "driver/project/project_sources.h"

namespace shaderport::driver::project {

// Where a line of a ported shader came from.
struct UserLine {
  const SourceFile* file = nullptr;  // the user's pass or Common; nullptr: generated
  uint32_t line = 0;                 // 1-based in `file`
};

struct PortedPass {
  const ProjectPass* pass = nullptr;
  const SourceFile* code = nullptr;  // the pass as the user wrote it
  PortResult result;                 // result.text: the complete shader
  // One entry per line of result.text (index 0: line 1).
  std::vector<UserLine> line_origins;
};

struct PortedProject {
  const ShaderToyProject* project = nullptr;
  ProjectSources sources;
  std::vector<PortedPass> passes;  // every pass but Common, in the project's order
  DiagnosticList diagnostics;      // all findings, each once (Common's are shared)
  bool validated = true;           // every pass's output compiled
};

// `options.mode` port; the pass kind and channel types come from the project.
PortedProject PortProject(const ProjectSources& project, const PortOptions& options,
                          SourceManager& sources);

// Fix mode: each pass and Common fixed as written (no header, no main()), one
// result per entry of `project.passes`.
std::vector<PortResult> FixProject(const ProjectSources& project, const PortOptions& options,
                                   SourceManager& sources);

// The sampler type the site declares for each channel of `pass`.
void SetChannelKinds(const ProjectPass& pass, PortOptions& options);

}  // namespace shaderport::driver::project
