#include "driver/html_report/project_entry.h"

#include "driver/check_projects.h"
#include "driver/html_report/png_base64.h"
#include "driver/html_report/report_steps.h"
#include "driver/project/folder_project.h"
#include "driver/project/port_document.h"
#include "driver/render_check/render_multipass.h"
#include "render/png_io.h"

namespace shaderport::driver {

std::filesystem::path ProjectOfReport(const FileReport& report) {
  if (report.file == nullptr) return {};
  if (const Embedding* embedding = report.file->Embedded(); embedding && embedding->container)
    return embedding->container->Name();
  const std::filesystem::path name(report.file->Name());
  if (IsProjectDocument(name)) return name;  // a document that could not be read
  return project::ProjectFolderOf(name);
}

void FillProjectEntry(const std::filesystem::path& project,
                      const std::vector<const FileReport*>& checked,
                      const HtmlReportOptions& options, SourceManager& sources,
                      ReportEntry& entry) {
  entry.path = project.string();
  entry.dialect = "shadertoy";
  entry.stage = "fragment";
  DiagnosticList all;
  for (const FileReport* report : checked) {
    for (const Diagnostic& diagnostic : report->diagnostics) all.push_back(diagnostic);
    for (ReportFinding& finding : DiagnosticFindings(report->file, report->diagnostics, sources))
      entry.check.findings.push_back(std::move(finding));
  }
  entry.check.status = StatusOf(all);
  entry.check.detail = std::to_string(checked.size()) + " passes; " +
                       (HasErrors(all) ? "the site's compiler rejects some" : "all compile");
  if (HasErrors(all) && all.front().rule_id == "input/invalid-project") {
    entry.port.detail = "not a readable project";
    entry.render.detail = "not rendered";
    return;
  }
  std::error_code error;
  const bool folder = std::filesystem::is_directory(project, error);
  const project::PortedDocument ported =
      folder ? project::PortFolder(project, PortOptions{}, sources)
             : project::PortDocument(project, ReadInputFile(project), PortOptions{}, sources);
  bool validated = !ported.read_failed && !ported.ported.empty();
  for (const project::PortedProject& one : ported.ported) validated = validated && one.validated;
  const PortResult findings = ported.Findings();
  entry.port.status = validated ? StatusOf(findings.diagnostics) : StepStatus::kFail;
  entry.port.detail =
      validated ? "every pass validates as WebGL2" : "some ported pass does not validate";
  entry.port.findings = DiagnosticFindings(findings.file, findings.diagnostics, sources);
  RenderFileOptions render_options;
  render_options.render = options.render;
  render_options.base.width = options.size;
  render_options.base.height = options.size;
  const RenderFileResult rendered = RenderProject(project, sources, render_options);
  entry.render.detail = "the project as the site draws it (every pass)";
  if (rendered.image) {
    entry.png = render::EncodePng(*rendered.image);
    entry.render.status = StatusOf(rendered.diagnostics);
  } else {
    entry.render.status =
        HasErrors(rendered.diagnostics) ? StepStatus::kFail : StepStatus::kSkipped;
  }
  entry.render.findings = DiagnosticFindings(rendered.file, rendered.diagnostics, sources);
}

}  // namespace shaderport::driver
