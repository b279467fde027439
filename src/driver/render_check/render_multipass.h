// ShaderToy multipass from the site's JSON export (the corpus format: an object with
// `passes[]`, each with `type`, `name`, `code`, `inputs[]`): Common is prepended to
// every pass, Buffers A-D are drawn each frame with ping-pong textures, then Image.
#pragma once

#include <filesystem>
#include <string_view>

#include "driver/render_check/render_file.h"

namespace shaderport::driver {

// Renders the shader in `json_text` (one JSON object). Pass codes become source files
// named "<name>#<pass name>" so that findings point at their lines.
RenderFileResult RenderShaderToyJson(std::string_view name, std::string_view json_text,
                                     SourceManager& sources, const RenderFileOptions& options);

// A ShaderToy project in any form shaderport reads (docs/projects.md): the site's
// API export or a corpus record (.json), a .jsonl file holding one project, or a
// project folder (a directory with shadertoy.toml).
RenderFileResult RenderProject(const std::filesystem::path& path, SourceManager& sources,
                               const RenderFileOptions& options);

// `shaderport render PATH`: a ShaderToy project (RenderProject) is drawn with all its
// passes; anything else is one shader (RenderFile).
RenderFileResult RenderInput(const std::filesystem::path& path, SourceManager& sources,
                             const RenderFileOptions& options);

}  // namespace shaderport::driver
