#include "driver/project/fix_document.h"

#include <memory>

#include "driver/project/json_code_rewrite.h"
#include "driver/project/load_document.h"
#include "driver/project/port_project.h"
#include "driver/project/project_sources.h"

namespace shaderport::driver::project {

FixedDocument FixDocument(const std::filesystem::path& path, InputText input,
                          const PortOptions& options, SourceManager& sources) {
  FixedDocument out;
  const std::string name = path.string();
  LoadedDocument loaded = LoadDocument(path, std::move(input), sources);
  out.document = loaded.document;
  // A document with problems is left as it is: rewriting part of it would hide them.
  if (!loaded.Usable()) {
    out.problems = std::move(loaded.problems);
    out.read_failed = true;
    return out;
  }
  const std::string_view text = out.document->Text();
  const ProjectDocument& read = *loaded.read;
  const auto container = std::make_shared<const SourceFile>(kNoFile, name, std::string(text));
  std::vector<CodeReplacement> replacements;
  const bool several = read.projects.size() > 1;
  for (size_t i = 0; i < read.projects.size(); ++i) {
    const ProjectSources registered =
        AddProjectSources(name, container, read.projects[i], i, several, sources);
    for (PortResult& result : FixProject(registered, options, sources))
      out.passes.push_back(std::move(result));
  }
  // Built once out.passes no longer moves: replacements point into its texts.
  size_t index = 0;
  for (size_t i = 0; i < read.projects.size(); ++i) {
    for (const ProjectPass& pass : read.projects[i].passes) {
      const PortResult& result = out.passes[index++];
      if (result.Changed()) replacements.push_back({&pass, result.text, &result.map});
    }
  }
  out.text = RewriteCodeStrings(text, std::move(replacements));
  return out;
}

}  // namespace shaderport::driver::project
