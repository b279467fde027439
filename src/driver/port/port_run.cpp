#include "driver/port/port_run.h"

#include <algorithm>

#include "driver/check_projects.h"
#include "driver/port/output_files.h"
#include "driver/port/port_project_files.h"
#include "driver/port/port_shader_files.h"
#include "driver/project/folder_project.h"

namespace shaderport::driver {

PortRun RunPort(std::vector<InputFile> inputs, const PortRunOptions& port_options,
                SourceManager& sources) {
  PortRunOptions options = port_options;
  options.port.mode = rule::PortMode::kPort;
  PortRun run;
  RelativeToCommonRoot(inputs);
  const bool page = options.layout == PortLayout::kPage;
  // A page may draw two files (a vertex and a fragment shader): pages check -o later.
  if (!options.output.empty() && inputs.size() != 1 && !page) {
    run.usage_error = "-o takes exactly one input file, and the paths hold " +
                      std::to_string(inputs.size()) + " (use --out-dir)";
    return run;
  }
  if (inputs.empty()) return run;  // --allow-empty, or all excluded
  // Standard output holds one shader: two would run together into one invalid text.
  if (options.output.empty() && options.out_dir.empty() && inputs.size() > 1 && !page) {
    run.usage_error = "the paths hold " + std::to_string(inputs.size()) +
                      " input files and standard output takes one shader: use --out-dir DIR";
    return run;
  }
  if (!options.output.empty()) {
    std::vector<std::filesystem::path> read;
    for (const InputFile& input : inputs) read.push_back(input.path);
    run.usage_error = OutputReplacesInput("-o", options.output, read);
    if (!run.usage_error.empty()) return run;
  }
  // ShaderToy projects (and any input of a page or folder) give several files or a page.
  const bool any_project = std::any_of(inputs.begin(), inputs.end(), [](const InputFile& input) {
    return IsProjectDocument(input.path) || !project::ProjectFolderOf(input.path).empty();
  });
  if (options.layout == PortLayout::kShaders && !any_project) {
    PortShaderFiles(inputs, options, sources, run);
  } else if (options.emit.kind != toolchain::EmitKind::kEssl) {
    run.usage_error = "ShaderToy projects are ported with --emit essl, html or folder";
  } else {
    PortProjectFiles(inputs, options, sources, run);
  }
  return run;
}

}  // namespace shaderport::driver
