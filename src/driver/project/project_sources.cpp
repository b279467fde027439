#include "driver/project/project_sources.h"

#include <memory>

namespace shaderport::driver::project {

std::string PassSourceName(const std::string& document, const ShaderToyProject& project,
                           size_t project_index, bool several_projects, const ProjectPass& pass) {
  if (!pass.file.empty()) return pass.file;
  std::string name = document + "#";
  if (several_projects)
    name += (project.id.empty() ? std::to_string(project_index) : project.id) + "/";
  return name + pass.name;
}

ProjectSources AddProjectSources(const std::string& document,
                                 const std::shared_ptr<const SourceFile>& container,
                                 const ShaderToyProject& project, size_t project_index,
                                 bool several_projects, SourceManager& sources) {
  ProjectSources out;
  out.project = &project;
  for (const ProjectPass& pass : project.passes) {
    std::string name = PassSourceName(document, project, project_index, several_projects, pass);
    const SourceFile* file = nullptr;
    if (pass.origin.document_offsets.empty() || container == nullptr) {
      file = &sources.Add(std::move(name), pass.code);
    } else {
      auto embedding = std::make_shared<Embedding>();
      embedding->container = container;
      embedding->logical_name = several_projects ? name.substr(document.size() + 1) : pass.name;
      embedding->offsets = pass.origin.document_offsets;
      file = &sources.AddEmbedded(std::move(name), pass.code, std::move(embedding));
    }
    out.passes.push_back({&pass, file});
    if (pass.kind == model::PassKind::kCommon && out.common == nullptr) out.common = file;
  }
  return out;
}

}  // namespace shaderport::driver::project
