#include "driver/render_check/render_multipass.h"

#include <algorithm>
#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "driver/check_projects.h"
#include "driver/project/folder_project.h"
#include "driver/project/json_project_reader.h"
#include "driver/project/record_json.h"
#include "driver/read_input.h"
#include "driver/render_check/composed_text.h"

namespace shaderport::driver {
namespace {

Diagnostic Note(SourceRange range, std::string message, Severity severity = Severity::kNote) {
  return MakeDiagnostic(severity,
                        severity == Severity::kNote ? "render/not-rendered" : "input/unreadable",
                        range, std::move(message));
}

struct PassInputs {
  model::ChannelKinds types{};
  std::array<int, 4> buffers = {-1, -1, -1, -1};
  std::array<bool, 4> fed{};  // the record names an input for the channel
  // What each channel of this pass reads, sampled how: the site binds every pass's
  // own inputs. A channel the record names nothing for is unbound.
  render::PassChannels channels = UnboundChannels();

  static render::PassChannels UnboundChannels() {
    render::PassChannels unbound{};
    for (render::PassChannel& channel : unbound) channel.kind = render::PassChannelKind::kUnbound;
    return unbound;
  }
};

// The input kinds as the project page binds them (src/driver/project/page/runtime.js,
// sourceOf): media become render's procedural textures of their shape; an unknown
// ctype (or a buffer input naming no buffer) binds nothing.
render::PassChannelKind ChannelKindOf(const std::string& ctype, int buffer) {
  using Kind = render::PassChannelKind;
  if (ctype == "buffer") return buffer >= 0 ? Kind::kBuffer : Kind::kUnbound;
  if (ctype == "texture" || ctype == "video" || ctype == "webcam" || ctype == "music" ||
      ctype == "musicstream" || ctype == "mic") {
    return Kind::kTexture;
  }
  // A Cube A pass's output too: render does not draw cube passes.
  if (ctype == "cubemap") return Kind::kCube;
  if (ctype == "volume") return Kind::kVolume;
  if (ctype == "keyboard") return Kind::kKeyboard;
  return Kind::kUnbound;
}

// Member `key` of `object` when it is a string, else `fallback` (nlohmann's
// value() throws on another type). RenderShaderToyJson validates the document
// first; this keeps the reads safe on their own.
std::string StringOr(const nlohmann::json& object, const char* key, std::string fallback) {
  const auto it = object.find(key);
  return it != object.end() && it->is_string() ? it->get<std::string>() : std::move(fallback);
}

// The input's `sampler`: filter nearest | linear | mipmap, wrap clamp | repeat,
// vflip (a boolean or "true"/"false"); absent members keep the site's defaults.
void ReadSampler(const nlohmann::json& input, render::PassChannel& channel) {
  const auto sampler = input.find("sampler");
  if (sampler == input.end() || !sampler->is_object()) return;
  // Compared as JSON values: a member of another type is ignored, not thrown on.
  const auto is = [&](const char* key, const char* word) {
    const auto it = sampler->find(key);
    return it != sampler->end() && *it == word;
  };
  if (is("filter", "nearest")) channel.filter = render::ChannelFilter::kNearest;
  if (is("filter", "linear")) channel.filter = render::ChannelFilter::kLinear;
  if (is("wrap", "clamp")) channel.wrap = render::ChannelWrap::kClamp;
  const auto vflip = sampler->find("vflip");
  if (vflip != sampler->end() && vflip->is_boolean()) channel.vflip = vflip->get<bool>();
  if (vflip != sampler->end() && vflip->is_string()) channel.vflip = *vflip == "true";
}

PassInputs InputsOf(const nlohmann::json& pass) {
  PassInputs inputs;
  const auto found = pass.find("inputs");
  if (found == pass.end() || !found->is_array()) return inputs;
  for (const auto& input : *found) {
    if (!input.is_object()) continue;
    const auto channel = input.find("channel");
    if (channel == input.end() || !channel->is_number_integer() || *channel < 0 || *channel > 3)
      continue;
    const auto c = channel->get<size_t>();
    const std::string ctype = StringOr(input, "ctype", "");
    inputs.types[c] = model::ChannelKindFromCtype(ctype);
    inputs.fed[c] = true;
    if (ctype == "buffer")
      inputs.buffers[c] = project::BufferIndexFromSource(StringOr(input, "src", "")).value_or(-1);
    render::PassChannel& bound = inputs.channels[c];
    bound = render::PassChannel{};
    bound.kind = ChannelKindOf(ctype, inputs.buffers[c]);
    bound.buffer = inputs.buffers[c];
    ReadSampler(input, bound);
  }
  return inputs;
}

}  // namespace

RenderFileResult RenderShaderToyJson(std::string_view name, std::string_view json_text,
                                     SourceManager& sources, const RenderFileOptions& options) {
  RenderFileResult result;
  result.dialect = "shadertoy";
  result.stage = "fragment";
  const SourceFile& json_file = sources.Add(std::string(name), std::string(json_text));
  result.file = &json_file;
  const SourceRange anchor{json_file.Id(), 0, 0};
  // Member by member (types, ranges, what is required), as check reads projects: a
  // problem is a finding on the document, at the member.
  const project::ProjectDocument validated = project::ReadShaderToyJson(json_text);
  if (!validated.problems.empty()) {
    const uint32_t at = std::min<uint32_t>(validated.problems.front().offset,
                                           static_cast<uint32_t>(json_text.size()));
    result.diagnostics.push_back(MakeDiagnostic(Severity::kError, "input/invalid-project",
                                                {json_file.Id(), at, at},
                                                validated.problems.front().message));
    return result;
  }
  const nlohmann::json shader = nlohmann::json::parse(json_text, nullptr, false);
  if (shader.is_discarded() || !shader.is_object() || !shader.contains("passes") ||
      !shader["passes"].is_array()) {
    result.diagnostics.push_back(
        Note(anchor, "not a ShaderToy JSON object with passes[]", Severity::kError));
    return result;
  }
  const SourceFile* common = options.common;
  const nlohmann::json* image = nullptr;
  std::vector<const nlohmann::json*> buffers;
  for (const auto& pass : shader["passes"]) {
    if (!pass.is_object() || !pass.contains("code") || !pass["code"].is_string()) continue;
    const std::string type = StringOr(pass, "type", "");
    if (type == "common") {
      common = &sources.Add(std::string(name) + "#Common", pass["code"].get<std::string>());
    } else if (type == "image") {
      image = &pass;
    } else if (type == "buffer") {
      buffers.push_back(&pass);
    }
  }
  if (image == nullptr) {
    result.diagnostics.push_back(Note(anchor, "the shader has no Image pass to render"));
    return result;
  }
  // Compose one pass: header, Common, code, epilogue, remembering the line map.
  DiagnosticList breaches;  // a pass past a resource limit: nothing is drawn
  auto compose = [&](const nlohmann::json& pass, model::PassKind type, const PassInputs& inputs) {
    const SourceFile& code = sources.Add(std::string(name) + "#" + StringOr(pass, "name", "pass"),
                                         pass["code"].get<std::string>());
    DetectedKind kind;
    kind.dialect = Dialect::kShaderToy;
    for (Diagnostic& d : RenderLimitBreaches(code, kind, common, sources))
      breaches.push_back(std::move(d));
    auto composed = std::make_shared<ComposedText>();
    composed->Append(validate::ShaderToyHeader(type, inputs.types), nullptr);
    if (common != nullptr) composed->Append(common->Text(), common);
    composed->Append(code.Text(), &code);
    composed->Append(validate::ShaderToyEpilogue(type), nullptr);
    return std::make_pair(composed, &code);
  };
  std::vector<std::shared_ptr<ComposedText>> buffer_texts;
  RenderFileOptions pass_options = options;
  for (const nlohmann::json* pass : buffers) {
    const int index = project::BufferIndexFromName(StringOr(*pass, "name", "")).value_or(-1);
    if (index < 0) continue;
    const PassInputs inputs = InputsOf(*pass);
    auto [composed, code] = compose(*pass, model::PassKind::kBuffer, inputs);
    render::BufferPass buffer;
    buffer.buffer = index;
    buffer.fragment_source = composed->Text();
    buffer.channel_buffers = inputs.buffers;
    buffer.channels = inputs.channels;
    pass_options.base.buffer_passes.push_back(std::move(buffer));
    buffer_texts.push_back(composed);
  }
  const PassInputs image_inputs = InputsOf(*image);
  pass_options.base.channel_buffers = image_inputs.buffers;
  pass_options.base.channels = image_inputs.channels;
  // A channel the record feeds nothing is empty on the site: nothing bound.
  for (size_t c = 0; c < 4; ++c)
    pass_options.base.inputs.channels[c].unbound = !image_inputs.fed[c];
  pass_options.channel_types = image_inputs.types;
  auto [composed, code] = compose(*image, model::PassKind::kImage, image_inputs);
  if (!breaches.empty()) {
    for (Diagnostic& d : breaches) result.diagnostics.push_back(std::move(d));
    return result;
  }
  PreparedShader prepared;
  prepared.fragment_text = composed->Text();
  prepared.main_sets_alpha = true;  // the Image pass
  prepared.anchor = SourceRange{code->Id(), 0, 0};
  prepared.user = code;
  // An init-capture: clang before 16 cannot capture a structured binding by name.
  prepared.map_line = [text = composed](model::Stage, uint32_t line) {
    return text->MapLine(line);
  };
  prepared.map_buffer_line = [buffer_texts](int pass, uint32_t line) -> std::optional<SourceRange> {
    if (pass < 0 || static_cast<size_t>(pass) >= buffer_texts.size()) return std::nullopt;
    return buffer_texts[static_cast<size_t>(pass)]->MapLine(line);
  };
  RenderPrepared(prepared, pass_options, result);
  return result;
}

RenderFileResult RenderProject(const std::filesystem::path& path, SourceManager& sources,
                               const RenderFileOptions& options) {
  RenderFileResult result;
  project::ProjectDocument document;
  std::string name = path.string();
  std::string text;  // the document's text, where findings point
  if (project::IsProjectFolder(path)) {
    document = project::ReadFolderProject(path);
    name = path.string();
  } else {
    InputText input = ReadInputFile(path);
    if (!input.text) {
      const SourceFile& empty = sources.Add(name, "");
      result.file = &empty;
      result.diagnostics.push_back(Note(empty.WholeRange(), input.message, Severity::kError));
      result.diagnostics.back().rule_id = input.rule_id;
      return result;
    }
    document = path.extension() == ".jsonl" ? project::ReadShaderToyJsonLines(*input.text)
                                            : project::ReadShaderToyJson(*input.text);
    text = std::move(*input.text);
  }
  std::string problem;
  uint32_t at = 0;
  if (!document.problems.empty()) {
    problem = document.problems.front().message;
    at = std::min<uint32_t>(document.problems.front().offset, static_cast<uint32_t>(text.size()));
  }
  if (problem.empty() && document.projects.size() != 1)
    problem = "the file holds " + std::to_string(document.projects.size()) +
              " projects; render draws one (split the file)";
  if (!problem.empty()) {
    const SourceFile& file = sources.Add(name, std::move(text));
    result.file = &file;
    result.diagnostics.push_back(Note({file.Id(), at, at}, problem, Severity::kError));
    result.diagnostics.back().rule_id = "input/invalid-project";
    return result;
  }
  // The corpus record is what RenderShaderToyJson reads as it is.
  if (path.extension() == ".json" &&
      document.projects.front().format == project::ProjectFormat::kCorpusRecord) {
    return RenderShaderToyJson(name, text, sources, options);
  }
  return RenderShaderToyJson(name, project::ToRecordJson(document.projects.front()), sources,
                             options);
}

RenderFileResult RenderInput(const std::filesystem::path& path, SourceManager& sources,
                             const RenderFileOptions& options) {
  std::error_code directory_error;
  const bool project =
      IsProjectDocument(path) ||
      (std::filesystem::is_directory(path, directory_error) && project::IsProjectFolder(path));
  return project ? RenderProject(path, sources, options) : RenderFile(path, sources, options);
}

}  // namespace shaderport::driver
