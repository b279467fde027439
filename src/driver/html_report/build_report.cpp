#include "driver/html_report/build_report.h"

#include <algorithm>
#include <map>

#include "driver/check_file.h"
#include "driver/check_pipeline.h"
#include "driver/html_report/png_base64.h"
#include "driver/html_report/project_entry.h"
#include "driver/html_report/render_ported.h"
#include "driver/html_report/report_steps.h"
#include "driver/input_files.h"
#include "driver/parallel_for.h"
#include "driver/port/port_file.h"
#include "driver/render_check/render_file.h"
#include "model/shipped_dialects.h"
#include "render/isolated_render.h"
#include "render/png_io.h"
#include "report/text_format.h"

namespace shaderport::driver {
namespace {

namespace fs = std::filesystem;

bool ReadFailed(const FileReport& report) {
  return std::any_of(report.diagnostics.begin(), report.diagnostics.end(), [](const auto& d) {
    return d.severity == Severity::kError && d.rule_id.starts_with("input/");
  });
}

// A ShaderToy pass compiles with the common.glsl beside it, as `check` does.
const SourceFile* CommonBeside(const fs::path& path, SourceManager& sources,
                               std::map<fs::path, const SourceFile*>& commons) {
  if (path.filename() == "common.glsl") return nullptr;
  const fs::path common_path = path.parent_path() / "common.glsl";
  if (auto it = commons.find(common_path); it != commons.end()) return it->second;
  std::error_code error;
  const SourceFile* common = nullptr;
  if (fs::is_regular_file(common_path, error)) {
    std::string message;
    common = LoadSharedFile(common_path, sources, message);
  }
  commons.emplace(common_path, common);
  return common;
}

struct Job {
  const FileReport* checked = nullptr;
  // A ShaderToy project: the document or folder, and all its passes' reports.
  std::filesystem::path project;
  std::vector<const FileReport*> project_reports;
  fs::path path;
  const SourceFile* common = nullptr;
  bool shader = false;  // false: a config file's own findings, shown but not ported
};

PortResult PortEntry(const Job& job, SourceManager& sources, ReportEntry& entry) {
  // The port reads the file as the check did (one decision per file, file_decision.h).
  PortOptions port_options;
  port_options.dialect = ParseDialect(job.checked->dialect);
  port_options.stage = model::ParseStage(job.checked->stage);
  if (!job.checked->harness.empty() && job.checked->harness != "shadertoy") {
    port_options.harness = model::FindBuiltinDialect(job.checked->harness);
  }
  PortResult ported = PortSource(*job.checked->file, job.common, port_options, sources);
  entry.port.status = ported.validated ? StatusOf(ported.diagnostics) : StepStatus::kFail;
  entry.port.detail = ported.validated ? (ported.Changed() ? "validated WebGL2 (changed)"
                                                           : "validated WebGL2 (unchanged)")
                                       : "the ported text does not validate";
  if (ported.narrowed) entry.port.detail += "; some fixes were dropped";
  entry.port.findings = DiagnosticFindings(ported.file, ported.diagnostics, sources);
  return ported;
}

void RenderEntry(const Job& job, const PortResult& ported, const HtmlReportOptions& options,
                 SourceManager& sources, ReportEntry& entry) {
  RenderFileOptions render_options;
  render_options.render = options.render;
  render_options.base.width = options.size;
  render_options.base.height = options.size;
  render_options.common = job.common;
  RenderFileResult rendered;
  if (ported.validated) {
    rendered = RenderPortResult(ported, render_options);
    entry.render.detail = "ported shader";
  } else {
    // The port failed: show what the site (or the browser) would draw from the original.
    render_options.channel_types = ChannelTypesOf(ported.text);
    rendered = RenderFile(job.path, sources, render_options);
    entry.render.detail = "original shader (the port did not validate)";
  }
  if (rendered.image) {
    entry.png = render::EncodePng(*rendered.image);
    entry.render.status = StatusOf(rendered.diagnostics);
  } else if (HasErrors(rendered.diagnostics)) {
    entry.render.status = StepStatus::kFail;
  } else {
    entry.render.status = StepStatus::kSkipped;
    entry.render.detail = "not rendered";
  }
  entry.render.findings = DiagnosticFindings(rendered.file != nullptr ? rendered.file : ported.file,
                                             rendered.diagnostics, sources);
}

}  // namespace

HtmlReportRun BuildHtmlReport(const HtmlReportOptions& options) {
  HtmlReportRun run;
  run.report.tool_version = options.tool_version;
  run.report.render_size = options.size;

  CheckOptions check_options;
  check_options.paths = options.paths;
  check_options.jobs = options.jobs;
  CheckRun checked = RunCheck(check_options);
  SortReport(checked.report);
  SourceManager& sources = *checked.sources;
  run.usage_errors = checked.usage_errors;
  run.usage_errors.insert(run.usage_errors.end(), checked.unmatched.begin(),
                          checked.unmatched.end());
  run.found_nothing = checked.found_nothing;
  run.report.errors = run.usage_errors;

  const InputFileList inputs = CollectInputFiles(options.paths);
  std::map<std::string, fs::path> input_by_name;
  for (const fs::path& path : inputs.files) input_by_name.emplace(path.string(), path);

  std::map<fs::path, const SourceFile*> commons;
  std::vector<Job> jobs;
  std::map<fs::path, size_t> project_jobs;  // a project's passes share one entry
  for (const FileReport& report : checked.report.files) {
    if (const fs::path project = ProjectOfReport(report); !project.empty()) {
      auto [it, added] = project_jobs.emplace(project, jobs.size());
      if (added) {
        Job job;
        job.checked = &report;
        job.project = project;
        jobs.push_back(std::move(job));
      }
      jobs[it->second].project_reports.push_back(&report);
      continue;
    }
    Job job;
    job.checked = &report;
    if (report.file != nullptr) {
      const auto it = input_by_name.find(std::string(report.file->Name()));
      job.shader = it != input_by_name.end() && !ReadFailed(report);
      if (it != input_by_name.end()) job.path = it->second;
    }
    // Common files are loaded before the parallel part, once per directory.
    if (job.shader) job.common = CommonBeside(job.path, sources, commons);
    jobs.push_back(std::move(job));
  }

  std::vector<ReportEntry> entries(jobs.size());
  // Each job thread ports, then draws with its own render worker
  // (render/isolated_render.h): one thread's glslang overlaps another's render.
  ParallelFor(jobs.size(), render::ParallelRenderJobs(options.jobs), [&](size_t i) {
    const Job& job = jobs[i];
    ReportEntry& entry = entries[i];
    if (!job.project.empty()) {
      FillProjectEntry(job.project, job.project_reports, options, sources, entry);
      return;
    }
    const FileReport& report = *job.checked;
    entry.shader = report.role != FileRole::kInput;
    entry.path = report.file != nullptr ? std::string(report.file->Name()) : "";
    entry.dialect = report.dialect;
    entry.stage = report.stage;
    entry.check.status = StatusOf(report.diagnostics);
    entry.check.detail = HasErrors(report.diagnostics) ? "glslang rejects it as the target "
                                                         "compiles it"
                                                       : "compiles as the target would";
    entry.check.findings = DiagnosticFindings(report.file, report.diagnostics, sources);
    if (!job.shader) {
      entry.port.detail = "not a readable shader";
      entry.render.detail = "not rendered";
      return;
    }
    const PortResult ported = PortEntry(job, sources, entry);
    RenderEntry(job, ported, options, sources, entry);
  });
  run.report.entries = std::move(entries);
  return run;
}

}  // namespace shaderport::driver
