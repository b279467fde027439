// A ShaderToy project as a folder: one file per tab and a small manifest,
// `shadertoy.toml`, for what the site keeps beside the code (name, channels).
//
//   common.glsl  buffer-a.glsl .. buffer-d.glsl  cube-a.glsl  sound.glsl  image.glsl
//
//   # shadertoy.toml
//   name = "Lightcycle"
//   [image]
//   channel0 = "buffer-a"                       # a tab's output, or an input kind:
//   channel1 = "keyboard"                       # texture, cubemap, volume, keyboard,
//   [buffer-a]                                  # video, audio
//   channel0 = { input = "buffer-a", filter = "linear", wrap = "clamp" }
//
// docs/projects.md describes the format; WriteFolderProject makes it from an export.
#pragma once

#include <filesystem>
#include <map>
#include <string>

#include "driver/project/json_project_reader.h"

namespace shaderport::driver::project {

inline constexpr std::string_view kManifestName = "shadertoy.toml";

// True when `directory` holds a shadertoy.toml.
bool IsProjectFolder(const std::filesystem::path& directory);

// The tab a file of a project folder stands for ("buffer-c.glsl" -> Buffer C).
std::optional<model::PassKind> TabOfFile(const std::filesystem::path& file, int& buffer);

// The project folder `file` is a tab file of ("" when none): its directory holds
// shadertoy.toml.
std::filesystem::path ProjectFolderOf(const std::filesystem::path& file);

// Reads the manifest and the tab files beside it; problems carry no offsets (0) and
// name the file in their message.
ProjectDocument ReadFolderProject(const std::filesystem::path& directory);

// The manifest's channel bindings for the pass file `file` (empty when the folder
// has no manifest or the manifest says nothing about the tab).
std::vector<ChannelBinding> FolderPassInputs(const std::filesystem::path& file);

// The files of the folder layout (name -> text): the tabs' code as written and a
// shadertoy.toml with the project's name, author, license and channels.
std::map<std::string, std::string> WriteFolderProject(const ShaderToyProject& project);

}  // namespace shaderport::driver::project
