#include "driver/check_pipeline.h"

#include <deque>
#include <map>
#include <mutex>
#include <optional>
#include <set>

#include "driver/check_cache.h"
#include "driver/check_file.h"
#include "driver/check_link.h"
#include "driver/check_projects.h"
#include "driver/check_shard.h"
#include "driver/config/config_lookup.h"
#include "driver/input_files.h"
#include "driver/input_selection.h"
#include "driver/largest_first.h"
#include "driver/parallel_for.h"
#include "render/isolated_render.h"

namespace shaderport::driver {
namespace {

namespace fs = std::filesystem;

// A ShaderToy directory with a common.glsl compiles it before every other pass
// of that directory, as the site compiles the Common tab into each pass.
const SourceFile* CommonFor(const fs::path& file, const CheckOptions& options,
                            std::map<fs::path, const SourceFile*>& commons, SourceManager& sources,
                            CheckRun& run) {
  if (file.filename() == "common.glsl") return nullptr;
  const fs::path common_path =
      options.common ? *options.common : file.parent_path() / "common.glsl";
  auto it = commons.find(common_path);
  if (it != commons.end()) return it->second;
  const SourceFile* common = nullptr;
  std::error_code error;
  if (options.common || fs::is_regular_file(common_path, error)) {
    std::string message;
    common = LoadSharedFile(common_path, sources, message);
    if (common == nullptr) run.usage_errors.push_back("--common " + message);
  }
  commons.emplace(common_path, common);
  return common;
}

// The tab that carries the picture of each project none of whose tabs has an error.
std::vector<size_t> ProjectsToDraw(const std::vector<FileJob>& jobs,
                                   const std::vector<FileReport>& reports) {
  std::map<std::string, size_t> image_of;
  std::set<std::string> failing;
  for (size_t i = 0; i < jobs.size(); ++i) {
    if (jobs[i].project.empty()) continue;
    if (HasErrors(reports[i].diagnostics)) failing.insert(jobs[i].project);
    // The Image tab, else the first tab checked (a folder's Buffer named alone).
    auto [it, added] = image_of.emplace(jobs[i].project, i);
    if (!added && jobs[i].pass == model::PassKind::kImage) it->second = i;
  }
  std::vector<size_t> images;
  for (const auto& [project, image] : image_of) {
    if (!failing.contains(project)) images.push_back(image);
  }
  return images;
}

}  // namespace

CheckRun RunCheck(const CheckOptions& options) {
  CheckRun run;
  run.report.sources = run.sources.get();
  SourceManager& sources = *run.sources;

  ConfigLookup configs(options.use_config, options.config, sources);
  InputSelectionOptions selection_options;
  selection_options.paths = options.paths;
  if (options.in_memory) selection_options.stdin_name = options.in_memory->name;
  selection_options.config = options.config;
  selection_options.use_config = options.use_config;
  selection_options.force_exclude = options.force_exclude;
  InputSelection inputs = SelectInputs(selection_options, configs);
  run.usage_errors = std::move(inputs.errors);
  if (!configs.ExplicitConfigError().empty()) return run;  // nothing is checked
  run.found_nothing = inputs.FoundNothing();
  run.excluded = inputs.dropped;
  run.unmatched = std::move(inputs.unmatched);

  std::map<fs::path, const SourceFile*> commons;
  std::deque<project::ProjectDocument> projects;  // the jobs of project passes point into them
  std::vector<FileReport> project_problems;
  std::vector<FileJob> jobs;
  std::error_code cwd_error;
  const fs::path working_directory = fs::current_path(cwd_error);
  for (const InputFile& input : inputs.files) {
    FileJob job;
    job.path = input.path;
    job.absolute_path = input.path.is_absolute() || working_directory.empty()
                            ? input.path
                            : working_directory / input.path;
    job.config = configs.For(input.path);
    if (options.in_memory) job.contents = &options.in_memory->contents;
    if (IsProjectDocument(input.path)) {
      AddProjectJobs(job, sources, projects, jobs, project_problems);
      continue;
    }
    job.common = CommonFor(input.path, options, commons, sources, run);
    ApplyFolderTab(job);
    jobs.push_back(std::move(job));
  }
  // Those read while walking, then those first read for a job (a named file's).
  std::vector<FileReport> config_problems = std::move(inputs.config_problems);
  for (FileReport& problem : configs.TakeProblems()) config_problems.push_back(std::move(problem));
  for (FileReport& problem : config_problems) {
    problem.role = FileRole::kInput;  // a .shaderport.toml is not a checked file
    run.report.files.push_back(std::move(problem));
  }
  for (FileReport& problem : project_problems) run.report.files.push_back(std::move(problem));
  // Over every input, before sharding: a pass reports its Common's findings only
  // when no shard checks Common as a file of its own.
  std::set<fs::path> canonical_inputs;
  for (const FileJob& job : jobs) {
    if (job.common != nullptr) {
      for (const FileJob& other : jobs) canonical_inputs.insert(fs::weakly_canonical(other.path));
      break;
    }
  }
  for (FileJob& job : jobs) {
    if (job.common == nullptr || job.source != nullptr) continue;  // JSON: Common is a job
    job.common_checked_separately =
        canonical_inputs.contains(fs::weakly_canonical(job.common->Name()));
  }
  if (options.shard) KeepShard(jobs, options, *options.shard, fs::current_path());

  std::mutex progress_mutex;
  size_t files_done = 0;
  auto file_done = [&] {
    if (!options.progress) return;
    const std::lock_guard lock(progress_mutex);
    options.progress(++files_done, jobs.size());
  };
  // --render results depend on Mesa and on time limits: such runs are not cached.
  std::optional<CheckCache> cache;
  if (options.cache_directory && !options.render && !options.in_memory && !options.explain_only)
    cache.emplace(options, jobs);
  const std::vector<std::pair<size_t, size_t>> programs = FindPrograms(jobs, options);
  // A file with no finding is not read again unless it is linked or rendered below, or
  // its text is shared (a project's pass): free its text now, so that a run over
  // thousands of files holds only those with findings.
  std::vector<bool> keep_text(jobs.size(), !options.release_clean_texts || options.render);
  for (const auto& [vertex, fragment] : programs) keep_text[vertex] = keep_text[fragment] = true;
  std::vector<FileReport> reports(jobs.size());
  // Several jobs take the largest files first; one job keeps the input order.
  const std::vector<size_t> order = options.jobs != 1 ? LargestFirst(jobs) : std::vector<size_t>{};
  ParallelFor(
      jobs.size(), options.jobs,
      [&](size_t i) {
        reports[i] = cache ? cache->Check(i, sources) : CheckFile(jobs[i], options, sources);
        const FileReport& report = reports[i];
        if (!keep_text[i] && jobs[i].source == nullptr && report.file != nullptr &&
            report.diagnostics.empty()) {
          sources.ReleaseText(report.file->Id());
        }
        if (!options.render) file_done();
      },
      order);
  if (cache) cache->Finish();
  // Programs link once both stages are checked (before renders, whose findings
  // must not stop a link).
  for (const auto& [vertex, fragment] : programs) {
    if (options.explain_only) break;
    LinkProgram(jobs[vertex], jobs[fragment], options, sources, reports[vertex], reports[fragment]);
  }
  // Each job thread draws with its own render worker (render/isolated_render.h),
  // so N jobs keep N workers busy; findings land in the file's own slot.
  // A ShaderToy project is drawn whole, as `render` draws it, once its tabs are done.
  if (options.render && !options.explain_only) {
    ParallelFor(jobs.size(), render::ParallelRenderJobs(options.jobs), [&](size_t i) {
      RenderCheckedFile(jobs[i], options, sources, reports[i], jobs[i].project.empty());
      file_done();
    });
    const std::vector<size_t> images = ProjectsToDraw(jobs, reports);
    ParallelFor(images.size(), render::ParallelRenderJobs(options.jobs), [&](size_t i) {
      RenderCheckedProject(jobs[images[i]], options, sources, reports[images[i]]);
    });
  }

  for (size_t i = 0; i < jobs.size(); ++i) {
    const Config* config = jobs[i].config;
    Severity fail_on = config != nullptr ? config->fail_on : Severity::kError;
    if (options.fail_on) fail_on = *options.fail_on;
    reports[i].fail_on = fail_on;  // kept: a baseline judges the run again
    if (!jobs[i].project.empty()) {
      reports[i].role = FileRole::kTab;
      reports[i].project = jobs[i].project;
    }
    for (const Diagnostic& diagnostic : reports[i].diagnostics) {
      if (diagnostic.severity >= fail_on) run.failed = true;
      if (diagnostic.rule_id.starts_with("internal/")) run.internal_error = true;
    }
  }
  for (const FileReport& config_report : run.report.files) {
    if (HasErrors(config_report.diagnostics)) run.failed = true;
  }
  for (FileReport& report : reports) run.report.files.push_back(std::move(report));
  return run;
}

}  // namespace shaderport::driver
