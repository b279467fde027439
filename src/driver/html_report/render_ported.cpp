#include "driver/html_report/render_ported.h"

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "driver/render_check/varying_feeder.h"

namespace shaderport::driver {
namespace {}  // namespace

model::ChannelKinds ChannelTypesOf(std::string_view text, model::ChannelKinds fallback) {
  model::ChannelKinds types = fallback;
  struct Kind {
    std::string_view sampler;
    model::ChannelKind type;
  };
  static constexpr Kind kKinds[] = {{"sampler2D", model::ChannelKind::k2D},
                                    {"samplerCube", model::ChannelKind::kCube},
                                    {"sampler3D", model::ChannelKind::k3D}};
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
  rendered.stage = result.output_stage == model::Stage::kVertex ? "vertex" : "fragment";
  if (result.file == nullptr || result.read_failed) return rendered;

  RenderFileOptions local = options;
  local.channel_types = ChannelTypesOf(result.text, options.channel_types);
  local.common = nullptr;  // the port already contains what it needs

  PreparedShader shader;
  shader.anchor = SourceRange{result.file->Id(), 0, 0};
  shader.user = result.file;
  if (result.output_stage == model::Stage::kVertex) {
    shader.vertex_text = result.text;
  } else {
    shader.fragment_text = result.text;
    // Inputs an app's vertex shader would write are fed by a generated one.
    shader.vertex_text = FeederVertexShader(result.text);
    shader.fullscreen_vertex = true;
    // The site shows an Image pass with alpha 1 whatever it writes (the port's main()
    // forces it too), so the render probe can take the alpha.
    shader.main_sets_alpha =
        result.kind.dialect == Dialect::kShaderToy && result.kind.pass == model::PassKind::kImage;
  }
  // Mesa's lines are lines of the ported text; its source map leads back to the user's file.
  struct LineMap {
    SourceFile ported;
    SourceMap map;
    FileId file;
  };
  auto lines = std::make_shared<LineMap>(
      LineMap{SourceFile(kNoFile, "<ported>", result.text), result.map, result.file->Id()});
  const model::Stage user_stage = result.output_stage;
  shader.map_line = [lines, user_stage](model::Stage stage,
                                        uint32_t line) -> std::optional<SourceRange> {
    if (stage != user_stage) return std::nullopt;  // the generated vertex shader
    if (line == 0 || line > lines->ported.LineCount()) return std::nullopt;
    const uint32_t begin = lines->ported.LineStart(line);
    const auto end = static_cast<uint32_t>(begin + lines->ported.LineText(line).size());
    if (lines->map.OutputSize() != lines->ported.Text().size()) {
      return SourceRange{lines->file, 0, 0};
    }
    const auto [first, last] = lines->map.ToOriginalRange(begin, end);
    return SourceRange{lines->file, first, last};
  };
  RenderPrepared(shader, local, rendered);
  return rendered;
}

}  // namespace shaderport::driver
