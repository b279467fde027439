// A project's passes as source files, so that findings read "doc.json#Buffer A:3:7".
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "driver/project/shadertoy_project.h"
#include "source/source_manager.h"

namespace shaderport::driver::project {

struct PassSource {
  const ProjectPass* pass = nullptr;
  const SourceFile* file = nullptr;  // the pass's code, named after its tab
};

struct ProjectSources {
  const ShaderToyProject* project = nullptr;
  std::vector<PassSource> passes;  // in the project's order, Common included
  const SourceFile* common = nullptr;
};

// "doc.json#Image"; with several projects in one document, the project's id (or its
// index when it has none) comes first: "all.jsonl#3d23D1/Image". Folder passes keep
// their own file name.
std::string PassSourceName(const std::string& document, const ShaderToyProject& project,
                           size_t project_index, bool several_projects, const ProjectPass& pass);

// `container` is the JSON document the project was read from (nullptr for a folder;
// one for all the document's projects): the passes are registered as embedded in
// it, so CI formats can point at its bytes.
ProjectSources AddProjectSources(const std::string& document,
                                 const std::shared_ptr<const SourceFile>& container,
                                 const ShaderToyProject& project, size_t project_index,
                                 bool several_projects, SourceManager& sources);

}  // namespace shaderport::driver::project
