// The check of one input file, after the run has decided its settings.
#pragma once

#include <filesystem>
#include <optional>

#include "driver/check_options.h"
#include "driver/config/config.h"
#include "driver/dialect.h"
#include "driver/read_input.h"
#include "report/check_report.h"
#include "source/source_manager.h"

namespace shaderport::driver {
namespace project {
struct ShaderToyProject;  // project/shadertoy_project.h
}  // namespace project

struct FileJob {
  std::filesystem::path path;
  std::filesystem::path absolute_path;     // `path` made absolute once (config globs, cache keys)
  const Config* config = nullptr;          // the .shaderport.toml that governs it, if any
  const SourceFile* common = nullptr;      // ShaderToy Common code to compile before it
  bool common_checked_separately = false;  // then Common's own findings are not repeated here
  // The file's contents when they were read elsewhere (--stdin); `path` then only
  // names the file and need not exist.
  const InputText* contents = nullptr;
  // A pass of a ShaderToy project: its code, already registered (embedded in its
  // JSON document), the tab it is and the sampler types its inputs give.
  const SourceFile* source = nullptr;
  std::optional<model::PassKind> pass;
  std::optional<model::ChannelKinds> channels;
  // A tab of a project (a JSON project or a project folder): which project, for the
  // summary's count ("" for a shader file).
  std::string project;
  // A tab of a JSON project: the whole project, drawn by --render as `render` draws it.
  const project::ShaderToyProject* shadertoy_project = nullptr;
};

// Thread-safe: adds the file (and generated text) to `sources` and never throws
// for bad input.
FileReport CheckFile(const FileJob& job, const CheckOptions& options, SourceManager& sources);

// Smoke-renders a file CheckFile found free of errors and adds the picture's
// findings, then applies suppressions and configuration, which --render defers to
// here. `draw` false only does the latter (a project's tab, drawn with its project).
// Thread-safe: each calling thread draws with its own render worker
// (render/isolated_render.h).
void RenderCheckedFile(const FileJob& job, const CheckOptions& options, SourceManager& sources,
                       FileReport& report, bool draw = true);

// --render for a ShaderToy project whose tabs were checked (after RenderCheckedFile
// without drawing): the whole project is drawn as `render` draws it (Buffers each
// frame, then Image), and the picture's findings join the Image tab's report.
void RenderCheckedProject(const FileJob& image_job, const CheckOptions& options,
                          SourceManager& sources, FileReport& image_report);

// Reads and registers a file that other files use (ShaderToy Common); nullptr
// and a diagnostic message in `error` when it cannot be used.
const SourceFile* LoadSharedFile(const std::filesystem::path& path, SourceManager& sources,
                                 std::string& error);

}  // namespace shaderport::driver
