#include "driver/project/port_document.h"

#include <algorithm>

#include "driver/project/folder_project.h"
#include "driver/project/html_page.h"
#include "driver/project/load_document.h"
#include "driver/render_check/varying_feeder.h"
#include "render/builtin_shaders.h"

namespace shaderport::driver::project {
namespace {

// A ported stage's text, or why there is none.
std::string StageText(const PortResult& result, std::string& errors) {
  if (result.HasOutput() && !result.text.empty()) return result.text;
  for (const Diagnostic& d : result.diagnostics) {
    if (d.severity == Severity::kError) errors += d.message + " [" + d.rule_id + "]\n";
  }
  if (errors.empty()) errors = "the port produced no shader text";
  return {};
}

// Each ported line's line in the user's file: by its last character the port copied
// (an edited start such as `attribute` -> `in` keeps the line), else its first; a
// line with neither (the added `#version`, outputs) is generated.
std::vector<PageLineRun> PortedLineRuns(const PortResult& result, const std::string& origin) {
  std::vector<LineOrigin> lines;
  if (result.file == nullptr) return {};
  const std::string& text = result.text;
  for (size_t begin = 0; begin < text.size();) {
    size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    const auto b = static_cast<uint32_t>(begin);
    const auto e = static_cast<uint32_t>(end);
    LineOrigin line;
    if (e > b && result.map.IsCopied(e - 1, e)) {
      line = {origin, result.file->LocationOf(result.map.ToOriginal(e - 1)).line};
    } else if (e > b && result.map.IsCopied(b, b + 1)) {
      line = {origin, result.file->LocationOf(result.map.ToOriginal(b)).line};
    }
    lines.push_back(line);
    begin = end + 1;
  }
  return LineRunsFromOrigins(lines);
}

std::string StemOf(const PortResult* result) {
  return result != nullptr && result->file != nullptr
             ? std::filesystem::path(result->file->Name()).filename().string()
             : std::string();
}

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
    for (const PortedPass& pass : project.passes)
      findings.converged = findings.converged && pass.result.converged;
  }
  return findings;
}

bool PortedDocument::Validated() const {
  if (read_failed) return false;
  return std::all_of(ported.begin(), ported.end(),
                     [](const PortedProject& project) { return project.validated; });
}

PortedDocument PortDocument(const std::filesystem::path& path, InputText input,
                            const PortOptions& options, SourceManager& sources, bool port) {
  PortedDocument out;
  const std::string name = path.string();
  LoadedDocument loaded = LoadDocument(path, std::move(input), sources);
  out.document = loaded.document;
  out.read = std::move(loaded.read);
  out.problems = std::move(loaded.problems);
  if (!out.problems.empty()) {
    out.read_failed = true;
    return out;
  }
  const std::string_view text = out.document->Text();
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
  pass.kind = model::PassKind::kImage;
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
      if (!pass.result.HasOutput()) continue;  // its findings say why
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

DocumentOutput ProgramPage(const PortResult* vertex, const PortResult* fragment) {
  PageProject page;
  PagePass pass;
  pass.tab_name = StemOf(fragment != nullptr ? fragment : vertex);
  page.name = vertex != nullptr && fragment != nullptr ? StemOf(vertex) + " + " + StemOf(fragment)
                                                       : pass.tab_name;
  pass.kind = model::PassKind::kImage;
  std::string errors;
  pass.fragment_shader =
      fragment != nullptr ? StageText(*fragment, errors) : std::string(render::kFlatFragmentShader);
  if (fragment != nullptr) pass.lines = PortedLineRuns(*fragment, StemOf(fragment));
  if (vertex != nullptr) {
    pass.vertex_shader = StageText(*vertex, errors);
    pass.vertex_lines = PortedLineRuns(*vertex, StemOf(vertex));
    pass.mesh = true;
  } else {
    pass.vertex_shader = FeederVertexShader(pass.fragment_shader);
    if (pass.vertex_shader.empty()) pass.vertex_shader = render::kFullScreenVertexShader;
  }
  // The page compiles nothing when a stage has no text: the panel says why.
  if (!errors.empty()) pass.fragment_shader.clear();
  pass.port_errors = errors;
  page.passes.push_back(std::move(pass));
  return {"", BuildProjectPage(page)};
}

}  // namespace shaderport::driver::project
