#include "driver/project/port_project.h"

#include <algorithm>
#include <set>
#include <tuple>

namespace shaderport::driver::project {
namespace {

// Moves a range in the joined Common + pass text back to the file it came from.
class JoinedTextMap {
 public:
  JoinedTextMap(const SourceFile& joined, const SourceFile* common, const SourceFile& code)
      : joined_(joined.Id()),
        common_(common),
        code_(code),
        code_start_(common != nullptr ? static_cast<uint32_t>(common->Text().size()) + 1 : 0) {}

  SourceRange Map(SourceRange range) const {
    if (range.file != joined_) return range;
    if (common_ != nullptr && range.begin < code_start_) {
      const auto end = std::min<uint32_t>(range.end, code_start_ - 1);
      return {common_->Id(), range.begin, std::max(range.begin, end)};
    }
    const uint32_t begin = range.begin >= code_start_ ? range.begin - code_start_ : 0;
    const uint32_t end = range.end >= code_start_ ? range.end - code_start_ : 0;
    return {code_.Id(), begin, std::max(begin, end)};
  }

  void Map(Diagnostic& diagnostic) const {
    diagnostic.range = Map(diagnostic.range);
    for (auto& note : diagnostic.notes) note.range = Map(note.range);
    // Fixes stand for edits of the joined text, which nobody writes back.
    diagnostic.fixes.clear();
  }

  UserLine LineOf(uint32_t joined_offset) const {
    const SourceRange range = Map(SourceRange{joined_, joined_offset, joined_offset});
    const SourceFile* file = range.file == code_.Id() ? &code_ : common_;
    return {file, file->LocationOf(range.begin).line};
  }

 private:
  FileId joined_;
  const SourceFile* common_;
  const SourceFile& code_;
  uint32_t code_start_;
};

std::vector<UserLine> LineOrigins(const PortResult& result, const JoinedTextMap& map) {
  std::vector<UserLine> lines;
  const std::string_view text = result.text;
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const auto begin = static_cast<uint32_t>(start);
    const bool copied = end > start && result.map.IsCopied(begin, static_cast<uint32_t>(end));
    lines.push_back(copied ? map.LineOf(result.map.ToOriginal(begin)) : UserLine{});
    if (end == text.size()) break;
    start = end + 1;
  }
  return lines;
}

bool SameFinding(const Diagnostic& a, const Diagnostic& b) {
  return std::tie(a.range.file, a.range.begin, a.range.end, a.rule_id, a.message) ==
         std::tie(b.range.file, b.range.begin, b.range.end, b.rule_id, b.message);
}

}  // namespace

void SetChannelKinds(const ProjectPass& pass, PortOptions& options) {
  for (int channel = 0; channel < 4; ++channel) {
    model::ChannelKind kind = model::ChannelKind::k2D;
    if (const ChannelBinding* input = pass.Input(channel)) {
      if (input->source == ChannelSource::kCubemap || input->source == ChannelSource::kCubeBuffer)
        kind = model::ChannelKind::kCube;
      if (input->source == ChannelSource::kVolume) kind = model::ChannelKind::k3D;
    }
    options.channels[channel] = kind;
  }
}

PortedProject PortProject(const ProjectSources& project, const PortOptions& options,
                          SourceManager& sources) {
  PortedProject out;
  out.project = project.project;
  out.sources = project;
  for (const PassSource& source : project.passes) {
    if (source.pass->kind == model::PassKind::kCommon) continue;
    PortOptions pass_options = options;
    pass_options.pass = source.pass->kind;
    pass_options.dialect = Dialect::kShaderToy;
    SetChannelKinds(*source.pass, pass_options);
    // The site compiles Common and the pass as one text: so does the port, whose
    // output is then a shader a page can compile on its own.
    std::string joined;
    if (project.common != nullptr) joined = std::string(project.common->Text()) + "\n";
    joined += source.file->Text();
    const SourceFile& joined_file = sources.Add(source.file->Name(), std::move(joined), true);
    const JoinedTextMap map(joined_file, project.common, *source.file);
    PortedPass ported;
    ported.pass = source.pass;
    ported.code = source.file;
    ported.result = PortSource(joined_file, nullptr, pass_options, sources);
    for (Diagnostic& diagnostic : ported.result.diagnostics) map.Map(diagnostic);
    for (Diagnostic& diagnostic : ported.result.fixed) map.Map(diagnostic);
    ported.line_origins = LineOrigins(ported.result, map);
    out.validated = out.validated && ported.result.validated;
    for (const Diagnostic& diagnostic : ported.result.diagnostics) {
      const auto same = [&](const Diagnostic& d) { return SameFinding(d, diagnostic); };
      if (std::none_of(out.diagnostics.begin(), out.diagnostics.end(), same))
        out.diagnostics.push_back(diagnostic);
    }
    out.passes.push_back(std::move(ported));
  }
  return out;
}

std::vector<PortResult> FixProject(const ProjectSources& project, const PortOptions& options,
                                   SourceManager& sources) {
  std::vector<PortResult> results;
  for (const PassSource& source : project.passes) {
    PortOptions pass_options = options;
    pass_options.mode = rule::PortMode::kFix;
    pass_options.pass = source.pass->kind;
    pass_options.dialect = Dialect::kShaderToy;
    SetChannelKinds(*source.pass, pass_options);
    const bool is_common = source.pass->kind == model::PassKind::kCommon;
    results.push_back(
        PortSource(*source.file, is_common ? nullptr : project.common, pass_options, sources));
  }
  return results;
}

}  // namespace shaderport::driver::project
