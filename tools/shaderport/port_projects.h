// `shaderport port` of ShaderToy JSON documents (and, for --emit html, of single
// ShaderToy passes): a shader per pass under --out-dir, or a page per project.
#pragma once

#include <string>
#include <vector>

#include "diag/diagnostic.h"
#include "driver/input_files.h"
#include "driver/port/port_file.h"

namespace shaderport::cli {

enum class ProjectEmit {
  kShaders,  // a WebGL2 shader per pass (--emit essl)
  kHtml,     // a page per project (--emit html)
  kFolder,   // the project folder layout, code as written (--emit folder)
};

struct ProjectPortTargets {
  std::string output;   // -o
  std::string out_dir;  // --out-dir
  ProjectEmit emit = ProjectEmit::kShaders;
  Severity fail_on = Severity::kError;  // --fail-on
  bool write_invalid = false;           // --write-invalid: write outputs that do not compile
};

// Ports `inputs` (each a .json/.jsonl document, or with `html` a ShaderToy pass),
// writes what they give and prints the findings; returns the exit code.
int PortProjectInputs(const std::vector<driver::InputFile>& inputs,
                      const driver::PortOptions& options, const ProjectPortTargets& targets,
                      SourceManager& sources);

}  // namespace shaderport::cli
