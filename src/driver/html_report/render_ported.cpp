#include "driver/html_report/render_ported.h"

#include <algorithm>
#include <cctype>
#include <memory>
#include <regex>
#include <string>
#include <vector>

namespace shaderport::driver {
namespace {

// Line starts of `text`, so a 1-based Mesa line becomes a byte range.
std::vector<uint32_t> LineStarts(std::string_view text) {
  std::vector<uint32_t> starts = {0};
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n') starts.push_back(static_cast<uint32_t>(i + 1));
  }
  return starts;
}

// A fragment shader written for an app's vertex shader reads varyings (`uv`,
// `vNormal`) that the renderer's full-screen triangle does not write. Each float `in`
// becomes a plain global set at the top of main() from the pixel position: 0..1 screen
// coordinates for 2D values, a normal facing the viewer for normals, a point in front of
// the camera otherwise. Lines are kept, so Mesa's line numbers still map.
std::string FeedFragmentInputs(std::string_view text, uint32_t width, uint32_t height) {
  std::string out;
  std::string writes;
  size_t begin = 0;
  while (begin < text.size()) {
    size_t end = text.find('\n', begin);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(begin, end - begin);
    const bool last = end == text.size();
    begin = end + 1;
    std::vector<std::string> words;
    if (line.starts_with("in ") && line.ends_with(";")) {
      const std::string_view body = line.substr(0, line.size() - 1);
      for (size_t at = 0; at < body.size();) {
        const size_t space = std::min(body.find(' ', at), body.size());
        if (space > at) words.emplace_back(body.substr(at, space - at));
        at = space + 1;
      }
    }
    std::string value;
    if (words.size() >= 3 && words.size() <= 4) {
      const std::string& type = words[words.size() - 2];
      std::string lower = words.back();
      for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (type == "float") {
        value = "t.x";
      } else if (type == "vec2") {
        value = "t";
      } else if (type == "vec3") {
        value =
            lower.find("norm") != std::string::npos ? "normalize(vec3(p, 1.0))" : "vec3(p, -2.0)";
      } else if (type == "vec4") {
        value = "vec4(p, -2.0, 1.0)";
      }
    }
    if (value.empty()) {
      out += line;  // ints need `flat` and a real vertex shader: left as they are
    } else {
      out += line.substr(3);  // the declaration without `in`
      writes += " " + words.back() + " = " + value + ";";
    }
    if (!last) out += '\n';
  }
  if (writes.empty()) return std::string(text);
  static const std::regex kMain(R"(void\s+main\s*\(\s*(void)?\s*\)\s*\{)");
  std::smatch match;
  if (!std::regex_search(out, match, kMain)) return std::string(text);
  const std::string setup = " vec2 t = gl_FragCoord.xy / vec2(" + std::to_string(width) + ".0, " +
                            std::to_string(height) + ".0); vec2 p = t * 2.0 - 1.0;" + writes;
  out.insert(static_cast<size_t>(match.position(0) + match.length(0)), setup);
  return out;
}

}  // namespace

validate::ChannelTypes ChannelTypesOf(std::string_view text, validate::ChannelTypes fallback) {
  validate::ChannelTypes types = fallback;
  struct Kind {
    std::string_view sampler;
    validate::ChannelType type;
  };
  static constexpr Kind kKinds[] = {{"sampler2D", validate::ChannelType::k2D},
                                    {"samplerCube", validate::ChannelType::kCube},
                                    {"sampler3D", validate::ChannelType::k3D}};
  for (size_t channel = 0; channel < 4; ++channel) {
    const std::string name = "iChannel" + std::to_string(channel) + ";";
    for (const Kind& kind : kKinds) {
      const std::string declaration = std::string(kind.sampler) + " " + name;
      if (text.find(declaration) != std::string_view::npos) types[channel] = kind.type;
    }
  }
  return types;
}

RenderFileResult RenderPortResult(const PortResult& result, const RenderFileOptions& options) {
  RenderFileResult rendered;
  rendered.file = result.file;
  rendered.dialect = "webgl2";
  rendered.stage = result.output_stage == Stage::kVertex ? "vertex" : "fragment";
  if (result.file == nullptr || result.read_failed) return rendered;

  RenderFileOptions local = options;
  local.channel_types = ChannelTypesOf(result.text, options.channel_types);
  local.common = nullptr;  // the port already contains what it needs

  PreparedShader shader;
  shader.anchor = SourceRange{result.file->Id(), 0, 0};
  shader.user = result.file;
  if (result.output_stage == Stage::kVertex) {
    shader.vertex_text = result.text;
  } else {
    shader.fragment_text = FeedFragmentInputs(result.text, options.base.width, options.base.height);
  }
  struct LineMap {
    std::vector<uint32_t> starts;
    SourceMap map;
    FileId file;
    uint32_t text_size;
  };
  auto lines =
      std::make_shared<LineMap>(LineMap{LineStarts(result.text), result.map, result.file->Id(),
                                        static_cast<uint32_t>(result.text.size())});
  const render::ShaderStage user_stage = result.output_stage == Stage::kVertex
                                             ? render::ShaderStage::kVertex
                                             : render::ShaderStage::kFragment;
  shader.map_line = [lines, user_stage](render::ShaderStage stage,
                                        uint32_t line) -> std::optional<SourceRange> {
    if (stage != user_stage) return std::nullopt;  // the generated vertex shader
    if (line == 0 || line > lines->starts.size()) return std::nullopt;
    const uint32_t begin = lines->starts[line - 1];
    const uint32_t end = line < lines->starts.size() ? lines->starts[line] - 1 : lines->text_size;
    if (lines->map.OutputSize() != lines->text_size) return SourceRange{lines->file, 0, 0};
    const auto [first, last] = lines->map.ToOriginalRange(begin, end);
    return SourceRange{lines->file, first, last};
  };
  RenderPrepared(shader, local, rendered);
  return rendered;
}

}  // namespace shaderport::driver
