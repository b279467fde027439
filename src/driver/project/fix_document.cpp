#include "driver/project/fix_document.h"

#include <memory>

#include "driver/project/json_code_rewrite.h"
#include "driver/project/json_project_reader.h"
#include "driver/project/port_project.h"
#include "driver/project/project_sources.h"

namespace shaderport::driver::project {

FixedDocument FixDocument(const std::filesystem::path& path, InputText input,
                          const PortOptions& options, SourceManager& sources) {
  FixedDocument out;
  const std::string name = path.string();
  if (!input.text) {
    out.document = &sources.Add(name, "");
    out.read_failed = true;
    out.problems.push_back(MakeDiagnostic(Severity::kError, std::move(input.rule_id),
                                          {out.document->Id(), 0, 0}, std::move(input.message)));
    return out;
  }
  out.document = &sources.Add(name, std::move(*input.text));
  const std::string_view text = out.document->Text();
  const ProjectDocument read =
      path.extension() == ".jsonl" ? ReadShaderToyJsonLines(text) : ReadShaderToyJson(text);
  for (const ProjectProblem& problem : read.problems) {
    out.problems.push_back(MakeDiagnostic(Severity::kError, "input/invalid-project",
                                          {out.document->Id(), problem.offset, problem.offset},
                                          problem.message));
  }
  // A document with problems is left as it is: rewriting part of it would hide them.
  if (!read.problems.empty() || read.projects.empty()) {
    if (read.projects.empty() && read.problems.empty()) {
      out.problems.push_back(MakeDiagnostic(Severity::kError, "input/invalid-project",
                                            {out.document->Id(), 0, 0},
                                            "the file holds no ShaderToy project"));
    }
    out.read_failed = true;
    return out;
  }
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
