#include "driver/project/json_project_reader.h"

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "base/limits.h"
#include "driver/project/json_code_strings.h"
#include "driver/project/json_members.h"
#include "driver/read_input.h"

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

// Exports spell a cube map pass either way.
std::optional<model::PassKind> PassKindFromType(std::string_view type) {
  return type == "cubemap" ? model::PassKind::kCube : model::ParsePassKind(type);
}

// One member of "inputs"; nullopt (with the problem reported) when it names no
// channel 0-3.
std::optional<ChannelBinding> ReadBinding(MemberReader input) {
  ChannelBinding binding;
  const std::optional<int64_t> channel = input.Integer("channel", 0, 3, Presence::kRequired);
  binding.ctype = input.EitherString("ctype", "type").value_or("");
  binding.src = input.EitherString("src", "filepath").value_or("");
  const json* id_member = input.Id("id");
  const json id = id_member != nullptr ? *id_member : json();
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
  if (const json* sampler_member = input.Object("sampler")) {
    MemberReader sampler(*sampler_member, input.PointerOf("sampler"), input.Problems());
    if (auto filter = sampler.String("filter"); filter && !filter->empty()) {
      binding.sampler.filter = *filter;
    }
    if (auto wrap = sampler.String("wrap"); wrap && !wrap->empty()) binding.sampler.wrap = *wrap;
    if (auto internal = sampler.String("internal"); internal && !internal->empty()) {
      binding.sampler.internal = *internal;
    }
    binding.sampler.vflip = sampler.Flag("vflip").value_or(true);
    binding.sampler.srgb = sampler.Flag("srgb").value_or(false);
  }
  if (!channel) return std::nullopt;
  binding.channel = static_cast<int>(*channel);
  return binding;
}

class Reader {
 public:
  Reader(std::string_view text, uint32_t base, ProjectDocument& out)
      : text_(text),
        base_(base),
        out_(out),
        first_problem_(out.problems.size()),
        codes_(FindStringValues(text, "code")) {}

  void ReadTop(const json& top) {
    if (top.is_array()) {
      for (size_t i = 0; i < top.size(); ++i) ReadShader(top[i], "/" + std::to_string(i));
    } else {
      ReadShader(top, "");
    }
    // A member's own problem first: "no Image pass" may only follow from it (a "type"
    // that is not a string), and render reports the first problem alone.
    const size_t member_start = out_.problems.size();
    ReportMemberProblems();
    std::rotate(out_.problems.begin() + static_cast<std::ptrdiff_t>(first_problem_),
                out_.problems.begin() + static_cast<std::ptrdiff_t>(member_start),
                out_.problems.end());
  }

 private:
  void Problem(std::string message, uint32_t offset = 0) {
    out_.problems.push_back({base_ + offset, std::move(message)});
  }

  // Members of the wrong type, out of range or missing, each at its value (found in
  // one scan of the text for all of them). A hostile document may hold millions: the
  // first kMaxDiagnosticsPerFile are kept, and a last problem says so.
  void ReportMemberProblems() {
    std::vector<MemberProblem>& kept = member_problems_.Kept();
    if (kept.empty()) return;
    std::set<std::string> pointers;
    for (const MemberProblem& problem : kept) pointers.insert(problem.pointer);
    const std::map<std::string, uint32_t> offsets = FindValueOffsets(text_, pointers);
    for (MemberProblem& problem : kept) {
      const auto at = offsets.find(problem.pointer);
      Problem(std::move(problem.message), at != offsets.end() ? at->second : 0);
    }
    if (kept.size() < member_problems_.Count()) {
      Problem(std::to_string(member_problems_.Count() - kept.size()) +
              " further problems with members were dropped");
    }
  }

  void ReadShader(const json& shader, const std::string& pointer) {
    if (!shader.is_object()) {
      Problem("expected a ShaderToy shader object at " + (pointer.empty() ? "/" : pointer) +
              ", not " + DescribeJsonValue(shader));
      return;
    }
    MemberReader top(shader, pointer, member_problems_);
    ShaderToyProject project;
    std::string passes_pointer;
    const json* passes = nullptr;
    const size_t problems_before = member_problems_.Count();
    if (const json* inner = shader.contains("Shader") ? top.Object("Shader") : nullptr) {
      MemberReader exported(*inner, top.PointerOf("Shader"), member_problems_);
      ReadExport(exported, project);
      passes = exported.Array("renderpass", Presence::kRequired);
      passes_pointer = exported.PointerOf("renderpass");
    } else if (shader.contains("renderpass")) {
      ReadExport(top, project);
      passes = top.Array("renderpass");
      passes_pointer = top.PointerOf("renderpass");
    } else if (shader.contains("passes")) {
      project.format = ProjectFormat::kCorpusRecord;
      project.id = top.String("id").value_or("");
      project.name = top.String("name").value_or("");
      project.author = top.String("author").value_or("");
      project.license = top.String("license").value_or("");
      project.description = top.String("description").value_or("");
      passes = top.Array("passes");
      passes_pointer = top.PointerOf("passes");
    }
    if (passes == nullptr) {
      // A member of the wrong type was reported; an object that is no shader at all is.
      if (member_problems_.Count() == problems_before) {
        Problem(
            "not a ShaderToy shader: expected {\"Shader\": {\"renderpass\": [...]}} or a "
            "record with \"passes\": [...]" +
            (pointer.empty() ? std::string() : " at " + pointer));
      }
      return;
    }
    for (size_t i = 0; i < passes->size(); ++i)
      ReadPass((*passes)[i], passes_pointer + "/" + std::to_string(i), project);
    CheckTabs(project);
    // The site always has an Image tab: it is what the page shows.
    if (project.Find(model::PassKind::kImage) == nullptr) {
      Problem("the project has no Image pass" +
              (pointer.empty() ? std::string() : " (at " + pointer + ")"));
    }
    out_.projects.push_back(std::move(project));
  }

  void ReadExport(MemberReader& shader, ShaderToyProject& project) {
    project.format = ProjectFormat::kApiExport;
    const json* info_member = shader.Object("info");
    if (info_member == nullptr) return;
    MemberReader info(*info_member, shader.PointerOf("info"), member_problems_);
    project.id = info.String("id").value_or("");
    project.name = info.String("name").value_or("");
    project.author = info.EitherString("username", "author").value_or("");
    project.description = info.String("description").value_or("");
  }

  void ReadPass(const json& pass, const std::string& pointer, ShaderToyProject& project) {
    if (!pass.is_object()) {
      member_problems_.Add(pointer, "a render pass at " + pointer + " must be an object, not " +
                                        DescribeJsonValue(pass));
      return;
    }
    MemberReader members(pass, pointer, member_problems_);
    const auto literal = codes_.find(pointer + "/code");
    const uint32_t where = literal != codes_.end() ? literal->second.begin : 0;
    if (literal == codes_.end()) {
      if (!pass.contains("code")) {
        Problem("a render pass without a \"code\" string at " + pointer);
      } else {
        members.String("code");  // reports the type it has instead
      }
      return;
    }
    const std::optional<std::string> type = members.String("type", Presence::kRequired);
    if (!type) return;
    const std::optional<model::PassKind> kind = PassKindFromType(*type);
    if (!kind) {
      Problem("unknown pass type \"" + *type + "\" at " + pointer +
                  " (the site has image, buffer, common, cubemap, sound)",
              where);
      return;
    }
    ProjectPass read;
    read.kind = *kind;
    read.name = members.String("name").value_or("");
    if (read.name.empty()) read.name = TabName(*kind);
    DecodedString code = DecodeWithOffsets(text_, literal->second);
    read.code = std::move(code.text);
    read.origin.literal_begin = base_ + literal->second.begin;
    read.origin.literal_end = base_ + literal->second.end;
    read.origin.document_offsets = std::move(code.offsets);
    if (base_ != 0)
      for (uint32_t& offset : read.origin.document_offsets) offset += base_;
    if (const json* inputs = members.Array("inputs")) {
      const std::string inputs_pointer = members.PointerOf("inputs");
      for (size_t i = 0; i < inputs->size(); ++i) {
        const json& input = (*inputs)[i];
        const std::string input_pointer = inputs_pointer + "/" + std::to_string(i);
        if (!input.is_object()) {
          member_problems_.Add(input_pointer, "an input at " + input_pointer +
                                                  " must be an object, not " +
                                                  DescribeJsonValue(input));
          continue;
        }
        std::optional<ChannelBinding> binding =
            ReadBinding(MemberReader(input, input_pointer, member_problems_));
        if (!binding || read.Input(binding->channel) != nullptr) continue;
        read.inputs.push_back(std::move(*binding));
      }
      std::sort(
          read.inputs.begin(), read.inputs.end(),
          [](const ChannelBinding& a, const ChannelBinding& b) { return a.channel < b.channel; });
    }
    const json* outputs = members.Array("outputs");
    if (read.kind == model::PassKind::kBuffer) {
      if (outputs != nullptr && !outputs->empty()) {
        const std::string first = members.PointerOf("outputs") + "/0";
        if (!(*outputs)[0].is_object()) {
          member_problems_.Add(first, "an output at " + first + " must be an object, not " +
                                          DescribeJsonValue((*outputs)[0]));
        } else if (const json* id = MemberReader((*outputs)[0], first, member_problems_).Id("id")) {
          read.output_buffer = BufferIndexFromId(*id).value_or(-1);
        }
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
        const bool same = a.kind == b.kind && (a.kind != model::PassKind::kBuffer ||
                                               a.output_buffer == b.output_buffer);
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
  size_t first_problem_;  // where this document's problems begin in out_ (.jsonl: many)
  std::map<std::string, JsonLiteral> codes_;
  MemberProblems member_problems_;
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
    if (line.size() > limits::kMaxFileBytes) {
      // The file's limit is per project: one too large a line is left out, not the file.
      out.problems.push_back({static_cast<uint32_t>(start),
                              "this line (one project) is " + MebibytesOf(line.size()) +
                                  " MiB, larger than the " + MebibytesOf(limits::kMaxFileBytes) +
                                  " MiB limit of one project; it was not read"});
    } else if (line.find_first_not_of(" \t\r") != std::string_view::npos) {
      ReadDocument(line, static_cast<uint32_t>(start), out);
    }
    start = end + 1;
  }
  return out;
}

}  // namespace shaderport::driver::project
