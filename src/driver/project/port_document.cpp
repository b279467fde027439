#include "driver/project/port_document.h"

#include "driver/project/folder_project.h"
#include "driver/project/html_page.h"

namespace shaderport::driver::project {
namespace {

// The site's ids are 6 letters and digits; anything else (a path, "..") is not
// used as a file name.
bool IsSafeFileName(std::string_view id) {
  if (id.empty() || id.size() > 64) return false;
  for (char c : id) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '-';
    if (!ok) return false;
  }
  return true;
}

std::string ProjectFolder(const PortedDocument& document, size_t index) {
  if (document.ported.size() <= 1) return "";
  const ShaderToyProject& project = *document.ported[index].project;
  return IsSafeFileName(project.id) ? project.id : std::to_string(index);
}

}  // namespace

PortResult PortedDocument::Findings() const {
  PortResult findings;
  findings.file = document;
  findings.read_failed = read_failed;
  findings.diagnostics = problems;
  for (const PortedProject& project : ported) {
    for (const Diagnostic& diagnostic : project.diagnostics)
      findings.diagnostics.push_back(diagnostic);
  }
  return findings;
}

PortedDocument PortDocument(const std::filesystem::path& path, InputText input,
                            const PortOptions& options, SourceManager& sources, bool port) {
  PortedDocument out;
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
  out.read = std::make_unique<ProjectDocument>(
      path.extension() == ".jsonl" ? ReadShaderToyJsonLines(text) : ReadShaderToyJson(text));
  for (const ProjectProblem& problem : out.read->problems) {
    out.problems.push_back(MakeDiagnostic(Severity::kError, "input/invalid-project",
                                          {out.document->Id(), problem.offset, problem.offset},
                                          problem.message));
  }
  if (out.read->projects.empty() && out.read->problems.empty()) {
    out.problems.push_back(MakeDiagnostic(Severity::kError, "input/invalid-project",
                                          {out.document->Id(), 0, 0},
                                          "the file holds no ShaderToy project"));
  }
  if (!out.problems.empty()) {
    out.read_failed = true;
    return out;
  }
  if (!port) return out;
  const auto container = std::make_shared<const SourceFile>(kNoFile, name, std::string(text));
  const bool several = out.read->projects.size() > 1;
  for (size_t i = 0; i < out.read->projects.size(); ++i) {
    const ProjectSources registered =
        AddProjectSources(name, container, out.read->projects[i], i, several, sources);
    out.ported.push_back(PortProject(registered, options, sources));
  }
  return out;
}

PortedDocument PortSinglePass(const std::filesystem::path& path, InputText input,
                              const PortOptions& options, SourceManager& sources) {
  PortedDocument out;
  if (!input.text) return PortDocument(path, std::move(input), options, sources);
  out.read = std::make_unique<ProjectDocument>();
  ShaderToyProject& project = out.read->projects.emplace_back();
  project.name = path.stem().string();
  ProjectPass& pass = project.passes.emplace_back();
  pass.kind = ShaderToyPass::kImage;
  pass.name = "Image";
  pass.code = std::move(*input.text);
  pass.file = path.string();
  const ProjectSources registered =
      AddProjectSources(path.string(), nullptr, project, 0, false, sources);
  out.document = registered.passes.front().file;
  out.ported.push_back(PortProject(registered, options, sources));
  return out;
}

PortedDocument PortFolder(const std::filesystem::path& directory, const PortOptions& options,
                          SourceManager& sources) {
  PortedDocument out;
  const std::filesystem::path manifest = directory / kManifestName;
  out.read = std::make_unique<ProjectDocument>(ReadFolderProject(directory));
  out.document = &sources.Add(manifest.string(), "");
  for (const ProjectProblem& problem : out.read->problems) {
    out.problems.push_back(MakeDiagnostic(Severity::kError, "input/invalid-project",
                                          {out.document->Id(), 0, 0}, problem.message));
  }
  if (!out.problems.empty() || out.read->projects.empty()) {
    out.read_failed = true;
    return out;
  }
  const ProjectSources registered =
      AddProjectSources(manifest.string(), nullptr, out.read->projects.front(), 0, false, sources);
  out.ported.push_back(PortProject(registered, options, sources));
  return out;
}

std::vector<DocumentOutput> FolderOutputs(const PortedDocument& document) {
  std::vector<DocumentOutput> outputs;
  if (document.read == nullptr) return outputs;
  const auto& projects = document.read->projects;
  for (size_t i = 0; i < projects.size(); ++i) {
    std::filesystem::path folder;
    if (projects.size() > 1)
      folder = IsSafeFileName(projects[i].id) ? projects[i].id : std::to_string(i);
    for (auto& [name, text] : WriteFolderProject(projects[i]))
      outputs.push_back({folder / name, std::move(text)});
  }
  return outputs;
}

std::vector<DocumentOutput> ShaderOutputs(const PortedDocument& document) {
  std::vector<DocumentOutput> outputs;
  for (size_t i = 0; i < document.ported.size(); ++i) {
    const std::filesystem::path folder = ProjectFolder(document, i);
    for (const PortedPass& pass : document.ported[i].passes) {
      std::filesystem::path file = FolderFileName(*pass.pass);
      file.replace_extension(".frag");
      outputs.push_back({folder / file, pass.result.text});
    }
  }
  return outputs;
}

std::vector<DocumentOutput> PageOutputs(const PortedDocument& document) {
  std::vector<DocumentOutput> outputs;
  for (size_t i = 0; i < document.ported.size(); ++i) {
    const std::string folder = ProjectFolder(document, i);
    outputs.push_back({std::filesystem::path(folder.empty() ? "" : folder + ".html"),
                       BuildProjectPage(PageFromPorted(document.ported[i]))});
  }
  return outputs;
}

}  // namespace shaderport::driver::project
