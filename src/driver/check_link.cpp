#include "driver/check_link.h"

#include <map>

#include "driver/front_end.h"
#include "rules/webgl/program_link.h"

namespace shaderport::driver {
namespace {

namespace fs = std::filesystem;

std::optional<model::Stage> StageOfPath(const fs::path& path) {
  const std::string extension = path.extension().string();
  if (extension == ".vert" || extension == ".vs") return model::Stage::kVertex;
  if (extension == ".frag" || extension == ".fs") return model::Stage::kFragment;
  return std::nullopt;
}

}  // namespace

std::vector<std::pair<size_t, size_t>> FindPrograms(const std::vector<FileJob>& jobs,
                                                    const CheckOptions& options) {
  std::vector<std::pair<size_t, size_t>> programs;
  std::map<fs::path, size_t> index_of;
  // Only --link names files another way than the walk did (a few syscalls per file).
  if (!options.links.empty()) {
    for (size_t i = 0; i < jobs.size(); ++i) index_of[fs::weakly_canonical(jobs[i].path)] = i;
  }
  for (const auto& [vertex, fragment] : options.links) {
    const auto v = index_of.find(fs::weakly_canonical(vertex));
    const auto f = index_of.find(fs::weakly_canonical(fragment));
    if (v != index_of.end() && f != index_of.end()) programs.emplace_back(v->second, f->second);
  }
  if (!options.links.empty()) return programs;
  // Same directory and stem: `blur.vert` + `blur.frag`.
  std::map<fs::path, std::pair<std::optional<size_t>, std::optional<size_t>>> by_stem;
  for (size_t i = 0; i < jobs.size(); ++i) {
    const std::optional<model::Stage> stage = StageOfPath(jobs[i].path);
    if (!stage) continue;
    auto& slot = by_stem[jobs[i].path.parent_path() / jobs[i].path.stem()];
    (*stage == model::Stage::kVertex ? slot.first : slot.second) = i;
  }
  for (const auto& [stem, pair] : by_stem) {
    if (pair.first && pair.second) programs.emplace_back(*pair.first, *pair.second);
  }
  return programs;
}

void LinkProgram(const FileJob& vertex_job, const FileJob& fragment_job,
                 const CheckOptions& options, SourceManager& sources, FileReport& vertex,
                 FileReport& fragment) {
  (void)vertex_job;
  (void)fragment_job;
  if (vertex.file == nullptr || fragment.file == nullptr) return;
  if (HasErrors(vertex.diagnostics) || HasErrors(fragment.diagnostics)) return;
  FrontEndOptions front_options;
  front_options.analyze = true;
  for (size_t i = 0; i < options.channels.size(); ++i) {
    front_options.channels[i] = options.channels[i].value_or(model::ChannelKind::k2D);
  }
  DetectedKind vertex_kind;
  vertex_kind.stage = model::Stage::kVertex;
  DetectedKind fragment_kind;
  fragment_kind.stage = model::Stage::kFragment;
  const FrontEndResult vs = RunFrontEnd(*vertex.file, nullptr, vertex_kind, sources, front_options);
  const FrontEndResult fs =
      RunFrontEnd(*fragment.file, nullptr, fragment_kind, sources, front_options);
  if (!vs.model || !fs.model) return;
  const rules::LinkStage vertex_stage{&vs.parsed.tree, &*vs.model, &vs.preprocessed,
                                      vs.preprocessed.version.number};
  const rules::LinkStage fragment_stage{&fs.parsed.tree, &*fs.model, &fs.preprocessed,
                                        fs.preprocessed.version.number};
  for (Diagnostic& diagnostic : rules::CheckProgramLink(vertex_stage, fragment_stage)) {
    FileReport& owner = diagnostic.range.file == vertex.file->Id() ? vertex : fragment;
    if (!diagnostic.range.Valid()) diagnostic.range = {fragment.file->Id(), 0, 0};
    owner.diagnostics.push_back(std::move(diagnostic));
  }
}

}  // namespace shaderport::driver
