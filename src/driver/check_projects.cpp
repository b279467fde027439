#include "driver/check_projects.h"

#include <memory>

#include "driver/project/folder_project.h"
#include "driver/project/load_document.h"
#include "driver/project/project_sources.h"
#include "driver/read_input.h"

namespace shaderport::driver {
namespace {

model::ChannelKinds ChannelTypesOf(const project::ProjectPass& pass) {
  model::ChannelKinds types{};
  for (const project::ChannelBinding& input : pass.inputs) {
    model::ChannelKind type = model::ChannelKind::k2D;
    if (input.source == project::ChannelSource::kCubemap ||
        input.source == project::ChannelSource::kCubeBuffer)
      type = model::ChannelKind::kCube;
    if (input.source == project::ChannelSource::kVolume) type = model::ChannelKind::k3D;
    types[static_cast<size_t>(input.channel)] = type;
  }
  return types;
}

}  // namespace

bool ApplyFolderTab(FileJob& job) {
  int buffer = -1;
  const std::optional<model::PassKind> tab = project::TabOfFile(job.path, buffer);
  const std::filesystem::path directory =
      job.path.parent_path().empty() ? std::filesystem::path(".") : job.path.parent_path();
  if (!tab || !project::IsProjectFolder(directory)) return false;
  project::ProjectPass pass;
  pass.inputs = project::FolderPassInputs(job.path);
  job.pass = *tab;
  job.channels = ChannelTypesOf(pass);
  job.project = directory.lexically_normal().string();
  return true;
}

bool IsProjectDocument(const std::filesystem::path& path) {
  const std::filesystem::path extension = path.extension();
  return extension == ".json" || extension == ".jsonl";
}

void AddProjectJobs(const FileJob& base, SourceManager& sources,
                    std::deque<project::ProjectDocument>& documents, std::vector<FileJob>& jobs,
                    std::vector<FileReport>& problems) {
  const std::string name = base.path.string();
  project::LoadedDocument loaded = project::LoadDocument(
      base.path, base.contents != nullptr ? *base.contents : ReadInputFile(base.path), sources);
  if (!loaded.problems.empty()) {
    FileReport report;
    report.file = loaded.document;
    report.dialect = "shadertoy";
    report.role = FileRole::kInput;
    report.diagnostics = std::move(loaded.problems);
    problems.push_back(std::move(report));
  }
  // The projects that were read are checked even beside a problem elsewhere.
  project::ProjectDocument& document = documents.emplace_back(std::move(*loaded.read));
  const std::string_view text = loaded.document->Text();
  const bool several = document.projects.size() > 1;
  const auto container = std::make_shared<const SourceFile>(kNoFile, name, std::string(text));
  for (size_t i = 0; i < document.projects.size(); ++i) {
    const project::ProjectSources registered =
        project::AddProjectSources(name, container, document.projects[i], i, several, sources);
    for (const project::PassSource& pass : registered.passes) {
      FileJob job = base;
      job.path = pass.file->Name();
      job.contents = nullptr;
      job.source = pass.file;
      job.pass = pass.pass->kind;
      job.channels = ChannelTypesOf(*pass.pass);
      job.project = name + "#" + std::to_string(i);
      job.shadertoy_project = &document.projects[i];
      job.common = pass.pass->kind == model::PassKind::kCommon ? nullptr : registered.common;
      // Common is a job of its own here: its findings are reported there, once.
      job.common_checked_separately = true;
      jobs.push_back(std::move(job));
    }
  }
}

}  // namespace shaderport::driver
