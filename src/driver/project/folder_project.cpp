#include "driver/project/folder_project.h"

#include <toml++/toml.h>

#include <array>
#include <sstream>

#include "driver/read_input.h"

namespace shaderport::driver::project {
namespace {

namespace fs = std::filesystem;

struct TabFile {
  const char* stem;
  model::PassKind kind;
  int buffer;
};

constexpr std::array<TabFile, 8> kTabs = {{
    {"common", model::PassKind::kCommon, -1},
    {"buffer-a", model::PassKind::kBuffer, 0},
    {"buffer-b", model::PassKind::kBuffer, 1},
    {"buffer-c", model::PassKind::kBuffer, 2},
    {"buffer-d", model::PassKind::kBuffer, 3},
    {"cube-a", model::PassKind::kCube, -1},
    {"sound", model::PassKind::kSound, -1},
    {"image", model::PassKind::kImage, -1},
}};

const TabFile* FindTab(std::string_view stem) {
  for (const TabFile& tab : kTabs)
    if (stem == tab.stem) return &tab;
  return nullptr;
}

// "buffer-a" (a tab's output) or an input kind, as the site's ctype.
bool BindingFromName(std::string_view name, ChannelBinding& binding) {
  if (const TabFile* tab = FindTab(name); tab != nullptr && tab->kind == model::PassKind::kBuffer) {
    binding.source = ChannelSource::kBuffer;
    binding.buffer = tab->buffer;
    binding.ctype = "buffer";
    binding.src = "/media/previz/buffer0" + std::to_string(tab->buffer) + ".png";
    binding.sampler.filter = "linear";
    binding.sampler.wrap = "clamp";
    return true;
  }
  static constexpr std::array<std::pair<std::string_view, ChannelSource>, 7> kKinds = {{
      {"cube-a", ChannelSource::kCubeBuffer},
      {"texture", ChannelSource::kTexture},
      {"cubemap", ChannelSource::kCubemap},
      {"volume", ChannelSource::kVolume},
      {"keyboard", ChannelSource::kKeyboard},
      {"video", ChannelSource::kVideo},
      {"audio", ChannelSource::kAudio},
  }};
  for (const auto& [kind_name, source] : kKinds) {
    if (name != kind_name) continue;
    binding.source = source;
    binding.ctype = source == ChannelSource::kCubeBuffer ? "cubemap"
                    : source == ChannelSource::kAudio    ? "music"
                                                         : std::string(name);
    if (source == ChannelSource::kCubeBuffer) binding.src = "/media/previz/cubemap00.png";
    return true;
  }
  return false;
}

std::string NameOfBinding(const ChannelBinding& binding) {
  switch (binding.source) {
    case ChannelSource::kBuffer:
      return std::string("buffer-") + static_cast<char>('a' + binding.buffer);
    case ChannelSource::kCubeBuffer:
      return "cube-a";
    case ChannelSource::kTexture:
      return "texture";
    case ChannelSource::kCubemap:
      return "cubemap";
    case ChannelSource::kVolume:
      return "volume";
    case ChannelSource::kKeyboard:
      return "keyboard";
    case ChannelSource::kVideo:
      return "video";
    case ChannelSource::kAudio:
      return "audio";
    case ChannelSource::kNone:
      break;
  }
  return "";
}

// Reads the [tab] table of a manifest; problems go to `problems`.
std::vector<ChannelBinding> ReadChannels(const toml::table& table, const std::string& where,
                                         std::vector<ProjectProblem>& problems) {
  std::vector<ChannelBinding> inputs;
  for (int channel = 0; channel < 4; ++channel) {
    const std::string key = "channel" + std::to_string(channel);
    const toml::node* node = table.get(key);
    if (node == nullptr) continue;
    ChannelBinding binding;
    binding.channel = channel;
    std::string name;
    if (const auto* text = node->as_string()) {
      name = text->get();
    } else if (const auto* spec = node->as_table()) {
      name = (*spec)["input"].value_or(std::string());
      binding.src = (*spec)["src"].value_or(std::string());
      if (!BindingFromName(name, binding)) {
        problems.push_back({0, where + "." + key + ": unknown input '" + name + "'"});
        continue;
      }
      binding.sampler.filter = (*spec)["filter"].value_or(binding.sampler.filter);
      binding.sampler.wrap = (*spec)["wrap"].value_or(binding.sampler.wrap);
      binding.sampler.vflip = (*spec)["vflip"].value_or(binding.sampler.vflip);
      inputs.push_back(std::move(binding));
      continue;
    }
    if (!BindingFromName(name, binding)) {
      problems.push_back({0, where + "." + key + ": unknown input '" + name +
                                 "' (buffer-a..buffer-d, cube-a, texture, cubemap, volume, "
                                 "keyboard, video, audio)"});
      continue;
    }
    inputs.push_back(std::move(binding));
  }
  return inputs;
}

std::optional<toml::table> ReadManifest(const fs::path& directory,
                                        std::vector<ProjectProblem>& problems) {
  const fs::path path = directory / kManifestName;
  InputText input = ReadInputFile(path);
  if (!input.text) {
    problems.push_back({0, path.string() + ": " + input.message});
    return std::nullopt;
  }
  try {
    return toml::parse(*input.text, path.string());
  } catch (const toml::parse_error& error) {
    // toml++ reports a user's syntax error this way; it becomes a diagnostic.
    problems.push_back({0, path.string() + ":" + std::to_string(error.source().begin.line) + ": " +
                               std::string(error.description())});
    return std::nullopt;
  }
}

}  // namespace

bool IsProjectFolder(const fs::path& directory) {
  std::error_code error;
  return fs::is_regular_file(directory / kManifestName, error);
}

std::optional<model::PassKind> TabOfFile(const fs::path& file, int& buffer) {
  if (file.extension() != ".glsl") return std::nullopt;
  const TabFile* tab = FindTab(file.stem().string());
  if (tab == nullptr) return std::nullopt;
  buffer = tab->buffer;
  return tab->kind;
}

fs::path ProjectFolderOf(const fs::path& file) {
  int buffer = -1;
  const fs::path directory = file.parent_path().empty() ? fs::path(".") : file.parent_path();
  if (!TabOfFile(file, buffer) || !IsProjectFolder(directory)) return {};
  return directory;
}

std::vector<ChannelBinding> FolderPassInputs(const fs::path& file) {
  const fs::path directory = file.parent_path().empty() ? fs::path(".") : file.parent_path();
  if (!IsProjectFolder(directory)) return {};
  std::vector<ProjectProblem> problems;
  const std::optional<toml::table> manifest = ReadManifest(directory, problems);
  if (!manifest) return {};
  const toml::table* table = (*manifest)[file.stem().string()].as_table();
  return table != nullptr ? ReadChannels(*table, file.stem().string(), problems)
                          : std::vector<ChannelBinding>{};
}

ProjectDocument ReadFolderProject(const fs::path& directory) {
  ProjectDocument out;
  const std::optional<toml::table> manifest = ReadManifest(directory, out.problems);
  if (!manifest) return out;
  ShaderToyProject project;
  project.format = ProjectFormat::kFolder;
  project.name = (*manifest)["name"].value_or(directory.filename().string());
  project.id = (*manifest)["id"].value_or(std::string());
  project.author = (*manifest)["author"].value_or(std::string());
  project.license = (*manifest)["license"].value_or(std::string());
  project.description = (*manifest)["description"].value_or(std::string());
  for (const TabFile& tab : kTabs) {
    const fs::path file = directory / (std::string(tab.stem) + ".glsl");
    std::error_code error;
    if (!fs::exists(file, error)) continue;
    InputText input = ReadInputFile(file);
    if (!input.text) {
      out.problems.push_back({0, file.string() + ": " + input.message});
      continue;
    }
    ProjectPass pass;
    pass.kind = tab.kind;
    pass.name = TabName(tab.kind, tab.buffer);
    pass.output_buffer = tab.buffer;
    pass.code = std::move(*input.text);
    pass.file = file.string();
    if (const toml::table* table = (*manifest)[tab.stem].as_table())
      pass.inputs = ReadChannels(*table, tab.stem, out.problems);
    project.passes.push_back(std::move(pass));
  }
  if (project.Find(model::PassKind::kImage) == nullptr)
    out.problems.push_back(
        {0, (directory / "image.glsl").string() + ": a project folder needs an Image tab"});
  out.projects.push_back(std::move(project));
  return out;
}

std::map<std::string, std::string> WriteFolderProject(const ShaderToyProject& project) {
  std::map<std::string, std::string> files;
  toml::table manifest;
  manifest.insert("name", project.name);
  if (!project.id.empty()) manifest.insert("id", project.id);
  if (!project.author.empty()) manifest.insert("author", project.author);
  if (!project.license.empty()) manifest.insert("license", project.license);
  for (const ProjectPass& pass : project.passes) {
    const std::string file = FolderFileName(pass);
    files[file] = pass.code;
    toml::table channels;
    for (const ChannelBinding& input : pass.inputs) {
      const std::string name = NameOfBinding(input);
      if (name.empty()) continue;
      toml::table spec;
      spec.insert("input", name);
      if (!input.src.empty()) spec.insert("src", input.src);
      spec.insert("filter", input.sampler.filter);
      spec.insert("wrap", input.sampler.wrap);
      spec.insert("vflip", input.sampler.vflip);
      channels.insert("channel" + std::to_string(input.channel), std::move(spec));
    }
    if (!channels.empty()) manifest.insert(file.substr(0, file.size() - 5), std::move(channels));
  }
  std::ostringstream text;
  text << "# A ShaderToy project as a folder (docs/projects.md).\n" << manifest << "\n";
  files[std::string(kManifestName)] = text.str();
  return files;
}

}  // namespace shaderport::driver::project
