// Writes the project page of a ShaderToy JSON project (the site's API export or a
// corpus record) with each pass composed as the site compiles it (header, Common,
// the pass, main(): validate/shadertoy_contract.h), the same text `render` draws.
// For tests/browser/project_pages.py, independent of the port pipeline; with
// --port, the passes go through the port (PortProject) and PageFromPorted instead.
//   project_page_fixture [--port] PROJECT.json OUT.html
#include <algorithm>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "driver/project/html_page.h"
#include "driver/project/json_project_reader.h"
#include "driver/project/port_project.h"
#include "validate/shadertoy_contract.h"

namespace {

namespace model = shaderport::model;
using namespace shaderport::driver::project;
namespace validate = shaderport::validate;

uint32_t Lines(const std::string& text) {
  auto n = static_cast<uint32_t>(std::count(text.begin(), text.end(), '\n'));
  if (!text.empty() && text.back() != '\n') ++n;
  return n;
}

std::string WithNewline(std::string text) {
  if (!text.empty() && text.back() != '\n') text += '\n';
  return text;
}

int BufferIndex(const nlohmann::json& input) {
  const std::string src = input.value("src", input.value("filepath", ""));
  const size_t at = src.find("buffer0");
  if (at != std::string::npos && at + 7 < src.size() && src[at + 7] >= '0' && src[at + 7] <= '3')
    return src[at + 7] - '0';
  static const char* const kIds[] = {"4dXGR8", "XsXGR8", "4sXGR8", "XdfGR8"};
  if (input.contains("id") && input["id"].is_string()) {
    for (int i = 0; i < 4; ++i)
      if (input["id"] == kIds[i]) return i;
  }
  return -1;
}

PageInput ReadInput(const nlohmann::json& input) {
  PageInput page;
  page.channel = input.value("channel", 0);
  const std::string ctype = input.value("ctype", input.value("type", ""));
  const std::string src = input.value("src", input.value("filepath", ""));
  if (ctype == "buffer") {
    page.kind = PageInputKind::kBuffer;
    page.buffer = BufferIndex(input);
  } else if (ctype == "cubemap") {
    const bool drawn = src.find("cubemap00") != std::string::npos ||
                       (input.contains("id") && input["id"] == "4dX3Rr");
    page.kind = drawn ? PageInputKind::kCubeBuffer : PageInputKind::kCubemap;
  } else if (ctype == "texture") {
    page.kind = PageInputKind::kTexture;
  } else if (ctype == "volume") {
    page.kind = PageInputKind::kVolume;
  } else if (ctype == "keyboard") {
    page.kind = PageInputKind::kKeyboard;
  } else if (ctype == "video" || ctype == "webcam") {
    page.kind = PageInputKind::kVideo;
  } else if (ctype == "music" || ctype == "musicstream" || ctype == "mic") {
    page.kind = PageInputKind::kAudio;
  }
  if (input.contains("sampler") && input["sampler"].is_object()) {
    const auto& s = input["sampler"];
    page.filter = s.value("filter", page.filter);
    page.wrap = s.value("wrap", page.wrap);
    if (s.contains("vflip")) page.vflip = s["vflip"] == true || s["vflip"] == "true";
  }
  return page;
}

// The page through the project reader and the port, as `port --emit html` makes it.
int PortedPage(const std::string& path, const std::string& text, std::ofstream& out) {
  const ProjectDocument document = ReadShaderToyJson(text);
  if (document.projects.empty()) {
    std::cerr << "no project in " << path << "\n";
    return 1;
  }
  shaderport::SourceManager sources;
  const auto container =
      std::make_shared<const shaderport::SourceFile>(shaderport::kNoFile, path, text);
  const ProjectSources registered =
      AddProjectSources(path, container, document.projects[0], 0, false, sources);
  const PortedProject ported = PortProject(registered, shaderport::driver::PortOptions{}, sources);
  out << BuildProjectPage(PageFromPorted(ported));
  return out ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  const bool port = argc == 4 && std::string(argv[1]) == "--port";
  if (argc != 3 && !port) {
    std::cerr << "usage: project_page_fixture [--port] PROJECT.json OUT.html\n";
    return 2;
  }
  if (port) ++argv;
  std::ifstream in(argv[1], std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  if (port) {
    std::ofstream out(argv[2], std::ios::binary);
    return PortedPage(argv[1], text.str(), out);
  }
  nlohmann::json doc = nlohmann::json::parse(text.str(), nullptr, false);
  if (doc.is_discarded()) {
    std::cerr << "not JSON: " << argv[1] << "\n";
    return 1;
  }
  PageProject project;
  nlohmann::json passes;
  if (doc.contains("Shader")) doc = doc["Shader"];
  if (doc.contains("renderpass")) {
    passes = doc["renderpass"];
    project.name = doc["info"].value("name", "");
    project.id = doc["info"].value("id", "");
  } else {
    passes = doc["passes"];
    project.name = doc.value("name", "");
    project.id = doc.value("id", "");
  }
  std::string common;
  for (const auto& pass : passes)
    if (pass.value("type", "") == "common") common = pass.value("code", "");
  for (const auto& pass : passes) {
    const std::string type = pass.value("type", "");
    if (type == "common") continue;
    PagePass page;
    page.tab_name = pass.value("name", "");
    if (type == "buffer") {
      page.kind = model::PassKind::kBuffer;
      page.output_buffer = page.tab_name.size() == 8 ? page.tab_name[7] - 'A' : -1;
    } else if (type == "cubemap" || type == "cube") {
      page.kind = model::PassKind::kCube;
    } else if (type == "sound") {
      page.kind = model::PassKind::kSound;
    }
    model::ChannelKinds channels{};
    for (const auto& input : pass.value("inputs", nlohmann::json::array())) {
      page.inputs.push_back(ReadInput(input));
      const int c = page.inputs.back().channel;
      if (c >= 0 && c < 4)
        channels[static_cast<size_t>(c)] = model::ChannelKindFromCtype(input.value("ctype", ""));
    }
    const std::string header = validate::ShaderToyHeader(page.kind, channels);
    const std::string code = pass.value("code", "");
    page.fragment_shader = header + (common.empty() ? "" : WithNewline(common)) +
                           WithNewline(code) + validate::ShaderToyEpilogue(page.kind);
    page.lines = ComposedLineRuns(Lines(header), Lines(common), Lines(code), page.tab_name);
    project.passes.push_back(std::move(page));
  }
  std::ofstream out(argv[2], std::ios::binary);
  out << BuildProjectPage(project);
  return out ? 0 : 1;
}
