#include "driver/project/json_project_reader.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "driver/project/json_code_strings.h"

namespace shaderport::driver::project {
namespace {

using nlohmann::json;

// Deeper nesting than any export has: refused before parsing, so that hostile input
// costs no stack.
constexpr size_t kMaxNesting = 64;

// The ids the site gives its generated outputs, in exports old (numbers) and new.
std::optional<int> BufferIndexFromId(const json& id) {
  if (id.is_number_integer()) {
    const auto value = id.get<int64_t>();
    if (value >= 257 && value <= 260) return static_cast<int>(value - 257);
    return std::nullopt;
  }
  if (!id.is_string()) return std::nullopt;
  static const char* const kIds[] = {"4dXGR8", "XsXGR8", "4sXGR8", "XdfGR8"};
  for (int i = 0; i < 4; ++i)
    if (id.get<std::string>() == kIds[i]) return i;
  return std::nullopt;
}

bool IsCubeBufferId(const json& id) {
  return (id.is_number_integer() && id.get<int64_t>() == 41) ||
         (id.is_string() && id.get<std::string>() == "4dX3Rr");
}

std::string StringMember(const json& object, const char* name, const char* other = nullptr) {
  auto it = object.find(name);
  if ((it == object.end() || !it->is_string()) && other != nullptr) it = object.find(other);
  return it != object.end() && it->is_string() ? it->get<std::string>() : std::string();
}

// The site writes booleans of samplers as strings ("true"); accept both.
bool FlagMember(const json& object, const char* name, bool fallback) {
  const auto it = object.find(name);
  if (it == object.end()) return fallback;
  if (it->is_boolean()) return it->get<bool>();
  if (it->is_string()) return it->get<std::string>() == "true";
  return fallback;
}

std::optional<ShaderToyPass> PassKindFromType(std::string_view type) {
  if (type == "image") return ShaderToyPass::kImage;
  if (type == "buffer") return ShaderToyPass::kBuffer;
  if (type == "common") return ShaderToyPass::kCommon;
  if (type == "cubemap" || type == "cube") return ShaderToyPass::kCubemap;
  if (type == "sound") return ShaderToyPass::kSound;
  return std::nullopt;
}

ChannelBinding ReadBinding(const json& input) {
  ChannelBinding binding;
  binding.channel = input.value("channel", -1);
  binding.ctype = StringMember(input, "ctype", "type");
  binding.src = StringMember(input, "src", "filepath");
  const json id = input.contains("id") ? input["id"] : json();
  const std::string& ctype = binding.ctype;
  if (ctype == "buffer") {
    binding.source = ChannelSource::kBuffer;
    const std::optional<int> index = BufferIndexFromSource(binding.src);
    binding.buffer = index ? *index : BufferIndexFromId(id).value_or(-1);
  } else if (ctype == "cubemap") {
    const bool drawn = IsCubeBufferId(id) || binding.src.find("cubemap00") != std::string::npos;
    binding.source = drawn ? ChannelSource::kCubeBuffer : ChannelSource::kCubemap;
  } else if (ctype == "texture") {
    binding.source = ChannelSource::kTexture;
  } else if (ctype == "volume") {
    binding.source = ChannelSource::kVolume;
  } else if (ctype == "keyboard") {
    binding.source = ChannelSource::kKeyboard;
  } else if (ctype == "video" || ctype == "webcam") {
    binding.source = ChannelSource::kVideo;
  } else if (ctype == "music" || ctype == "musicstream" || ctype == "mic") {
    binding.source = ChannelSource::kAudio;
  }
  const auto sampler = input.find("sampler");
  if (sampler != input.end() && sampler->is_object()) {
    const std::string filter = StringMember(*sampler, "filter");
    const std::string wrap = StringMember(*sampler, "wrap");
    const std::string internal = StringMember(*sampler, "internal");
    if (!filter.empty()) binding.sampler.filter = filter;
    if (!wrap.empty()) binding.sampler.wrap = wrap;
    if (!internal.empty()) binding.sampler.internal = internal;
    binding.sampler.vflip = FlagMember(*sampler, "vflip", true);
    binding.sampler.srgb = FlagMember(*sampler, "srgb", false);
  }
  return binding;
}

class Reader {
 public:
  Reader(std::string_view text, uint32_t base, ProjectDocument& out)
      : text_(text), base_(base), out_(out), codes_(FindStringValues(text, "code")) {}

  void ReadTop(const json& top) {
    if (top.is_array()) {
      for (size_t i = 0; i < top.size(); ++i) ReadShader(top[i], "/" + std::to_string(i));
    } else {
      ReadShader(top, "");
    }
  }

 private:
  void Problem(std::string message, uint32_t offset = 0) {
    out_.problems.push_back({base_ + offset, std::move(message)});
  }

  void ReadShader(const json& shader, const std::string& pointer) {
    if (!shader.is_object()) {
      Problem("expected a ShaderToy shader object at " + (pointer.empty() ? "/" : pointer));
      return;
    }
    ShaderToyProject project;
    std::string passes_pointer;
    const json* passes = nullptr;
    if (shader.contains("Shader") && shader["Shader"].is_object()) {
      ReadExport(shader["Shader"], project);
      passes = Member(shader["Shader"], "renderpass");
      passes_pointer = pointer + "/Shader/renderpass";
    } else if (shader.contains("renderpass")) {
      ReadExport(shader, project);
      passes = Member(shader, "renderpass");
      passes_pointer = pointer + "/renderpass";
    } else if (shader.contains("passes")) {
      project.format = ProjectFormat::kCorpusRecord;
      project.id = StringMember(shader, "id");
      project.name = StringMember(shader, "name");
      project.author = StringMember(shader, "author");
      project.license = StringMember(shader, "license");
      project.description = StringMember(shader, "description");
      passes = Member(shader, "passes");
      passes_pointer = pointer + "/passes";
    }
    if (passes == nullptr) {
      Problem(
          "not a ShaderToy shader: expected {\"Shader\": {\"renderpass\": [...]}} or a "
          "record with \"passes\": [...]" +
          (pointer.empty() ? std::string() : " at " + pointer));
      return;
    }
    for (size_t i = 0; i < passes->size(); ++i)
      ReadPass((*passes)[i], passes_pointer + "/" + std::to_string(i), project);
    CheckTabs(project);
    // The site always has an Image tab: it is what the page shows.
    if (project.Find(ShaderToyPass::kImage) == nullptr) {
      Problem("the project has no Image pass" +
              (pointer.empty() ? std::string() : " (at " + pointer + ")"));
    }
    out_.projects.push_back(std::move(project));
  }

  const json* Member(const json& object, const char* name) {
    const auto it = object.find(name);
    if (it == object.end() || !it->is_array()) return nullptr;
    return &*it;
  }

  static void ReadExport(const json& shader, ShaderToyProject& project) {
    project.format = ProjectFormat::kApiExport;
    const auto info = shader.find("info");
    if (info == shader.end() || !info->is_object()) return;
    project.id = StringMember(*info, "id");
    project.name = StringMember(*info, "name");
    project.author = StringMember(*info, "username", "author");
    project.description = StringMember(*info, "description");
  }

  void ReadPass(const json& pass, const std::string& pointer, ShaderToyProject& project) {
    const auto literal = codes_.find(pointer + "/code");
    const uint32_t where = literal != codes_.end() ? literal->second.begin : 0;
    if (!pass.is_object() || literal == codes_.end()) {
      Problem("a render pass without a \"code\" string at " + pointer, where);
      return;
    }
    const std::string type = StringMember(pass, "type");
    const std::optional<ShaderToyPass> kind = PassKindFromType(type);
    if (!kind) {
      Problem("unknown pass type \"" + type + "\" at " + pointer +
                  " (the site has image, buffer, common, cubemap, sound)",
              where);
      return;
    }
    ProjectPass read;
    read.kind = *kind;
    read.name = StringMember(pass, "name");
    if (read.name.empty()) read.name = TabName(*kind);
    DecodedString code = DecodeWithOffsets(text_, literal->second);
    read.code = std::move(code.text);
    read.origin.literal_begin = base_ + literal->second.begin;
    read.origin.literal_end = base_ + literal->second.end;
    read.origin.document_offsets = std::move(code.offsets);
    if (base_ != 0)
      for (uint32_t& offset : read.origin.document_offsets) offset += base_;
    if (const auto inputs = pass.find("inputs"); inputs != pass.end() && inputs->is_array()) {
      for (const json& input : *inputs) {
        if (!input.is_object()) continue;
        ChannelBinding binding = ReadBinding(input);
        if (binding.channel < 0 || binding.channel > 3 || read.Input(binding.channel) != nullptr)
          continue;
        read.inputs.push_back(std::move(binding));
      }
      std::sort(
          read.inputs.begin(), read.inputs.end(),
          [](const ChannelBinding& a, const ChannelBinding& b) { return a.channel < b.channel; });
    }
    if (read.kind == ShaderToyPass::kBuffer) {
      if (const auto outputs = pass.find("outputs");
          outputs != pass.end() && outputs->is_array() && !outputs->empty() &&
          (*outputs)[0].is_object() && (*outputs)[0].contains("id")) {
        read.output_buffer = BufferIndexFromId((*outputs)[0]["id"]).value_or(-1);
      }
      if (read.output_buffer < 0) read.output_buffer = BufferIndexFromName(read.name).value_or(-1);
      if (read.output_buffer < 0) {
        Problem("buffer pass \"" + read.name + "\" names no Buffer A-D output", where);
        return;
      }
    }
    project.passes.push_back(std::move(read));
  }

  // The site has one tab of each kind (four buffers): a second one is an error.
  void CheckTabs(const ShaderToyProject& project) {
    for (size_t i = 0; i < project.passes.size(); ++i) {
      for (size_t j = 0; j < i; ++j) {
        const ProjectPass& a = project.passes[j];
        const ProjectPass& b = project.passes[i];
        const bool same = a.kind == b.kind &&
                          (a.kind != ShaderToyPass::kBuffer || a.output_buffer == b.output_buffer);
        if (same) {
          Problem("a second \"" + b.name + "\" pass: the site has one of each",
                  b.origin.literal_begin - base_);
          break;
        }
      }
    }
  }

  std::string_view text_;
  uint32_t base_;
  ProjectDocument& out_;
  std::map<std::string, JsonLiteral> codes_;
};

size_t NestingDepth(std::string_view text) {
  size_t depth = 0;
  size_t deepest = 0;
  bool in_string = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;
      if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '{' || c == '[') {
      deepest = std::max(deepest, ++depth);
    } else if ((c == '}' || c == ']') && depth > 0) {
      --depth;
    }
  }
  return deepest;
}

void ReadDocument(std::string_view text, uint32_t base, ProjectDocument& out) {
  if (NestingDepth(text) > kMaxNesting) {
    out.problems.push_back({base, "JSON nested deeper than " + std::to_string(kMaxNesting) +
                                      " levels: not a ShaderToy export"});
    return;
  }
  json top;
  try {
    top = json::parse(text);
  } catch (const json::parse_error& error) {
    // The library's own error carries the byte; it becomes the user's diagnostic.
    const size_t at = error.byte > 0 ? error.byte - 1 : 0;
    std::string message = error.what();
    const size_t detail = message.find("syntax error");
    out.problems.push_back(
        {base + static_cast<uint32_t>(std::min(at, text.size())),
         "invalid JSON: " + (detail != std::string::npos ? message.substr(detail) : message)});
    return;
  } catch (const json::exception& error) {
    // Also thrown while parsing: a number too large for a double (out_of_range 406).
    const std::string message = error.what();
    const size_t detail = message.find("] ");
    out.problems.push_back(
        {base,
         "invalid JSON: " + (detail != std::string::npos ? message.substr(detail + 2) : message)});
    return;
  }
  Reader(text, base, out).ReadTop(top);
}

}  // namespace

ProjectDocument ReadShaderToyJson(std::string_view text) {
  ProjectDocument out;
  ReadDocument(text, 0, out);
  return out;
}

ProjectDocument ReadShaderToyJsonLines(std::string_view text) {
  ProjectDocument out;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(start, end - start);
    if (line.find_first_not_of(" \t\r") != std::string_view::npos)
      ReadDocument(line, static_cast<uint32_t>(start), out);
    start = end + 1;
  }
  return out;
}

}  // namespace shaderport::driver::project
