#include "driver/check_projects.h"

#include <memory>

#include "driver/project/folder_project.h"
#include "driver/project/project_sources.h"
#include "driver/read_input.h"

namespace shaderport::driver {
namespace {

validate::ChannelTypes ChannelTypesOf(const project::ProjectPass& pass) {
  validate::ChannelTypes types{};
  for (const project::ChannelBinding& input : pass.inputs) {
    validate::ChannelType type = validate::ChannelType::k2D;
    if (input.source == project::ChannelSource::kCubemap ||
        input.source == project::ChannelSource::kCubeBuffer)
      type = validate::ChannelType::kCube;
    if (input.source == project::ChannelSource::kVolume) type = validate::ChannelType::k3D;
    types[static_cast<size_t>(input.channel)] = type;
  }
  return types;
}

}  // namespace

bool ApplyFolderTab(FileJob& job) {
  int buffer = -1;
  const std::optional<ShaderToyPass> tab = project::TabOfFile(job.path, buffer);
  const std::filesystem::path directory =
      job.path.parent_path().empty() ? std::filesystem::path(".") : job.path.parent_path();
  if (!tab || !project::IsProjectFolder(directory)) return false;
  project::ProjectPass pass;
  pass.inputs = project::FolderPassInputs(job.path);
  job.pass = *tab;
  job.channels = ChannelTypesOf(pass);
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
  InputText input = base.contents != nullptr ? *base.contents : ReadInputFile(base.path);
  if (!input.text) {
    FileReport report;
    report.file = &sources.Add(name, "");
    report.diagnostics.push_back(MakeDiagnostic(Severity::kError, std::move(input.rule_id),
                                                {report.file->Id(), 0, 0},
                                                std::move(input.message)));
    problems.push_back(std::move(report));
    return;
  }
  const bool lines = base.path.extension() == ".jsonl";
  project::ProjectDocument& document =
      documents.emplace_back(lines ? project::ReadShaderToyJsonLines(*input.text)
                                   : project::ReadShaderToyJson(*input.text));
  const std::string& text = *input.text;
  if (!document.problems.empty() || document.projects.empty()) {
    FileReport report;
    report.file = &sources.Add(name, text);
    report.dialect = "shadertoy";
    for (const project::ProjectProblem& problem : document.problems) {
      report.diagnostics.push_back(
          MakeDiagnostic(Severity::kError, "input/invalid-project",
                         {report.file->Id(), problem.offset, problem.offset}, problem.message));
    }
    if (document.projects.empty() && document.problems.empty()) {
      report.diagnostics.push_back(MakeDiagnostic(Severity::kError, "input/invalid-project",
                                                  {report.file->Id(), 0, 0},
                                                  "the file holds no ShaderToy project"));
    }
    problems.push_back(std::move(report));
  }
  const bool several = document.projects.size() > 1;
  const auto container = std::make_shared<const SourceFile>(kNoFile, name, text);
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
      job.common = pass.pass->kind == ShaderToyPass::kCommon ? nullptr : registered.common;
      // Common is a job of its own here: its findings are reported there, once.
      job.common_checked_separately = true;
      jobs.push_back(std::move(job));
    }
  }
}

}  // namespace shaderport::driver
