#include "driver/check_pipeline.h"

#include <map>

#include "driver/check_file.h"
#include "driver/check_link.h"
#include "driver/config/find_config.h"
#include "driver/input_files.h"
#include "driver/parallel_for.h"

namespace shaderport::driver {
namespace {

namespace fs = std::filesystem;

// Configs are found and parsed once per file, before the parallel part, so
// that every job sees a finished Config. Their own errors become a report
// entry of the config file.
class ConfigCache {
 public:
  ConfigCache(const CheckOptions& options, SourceManager& sources, CheckRun& run)
      : options_(options), sources_(sources), run_(run) {
    if (options.use_config && options.config) explicit_ = Load(*options.config);
  }

  const Config* For(const fs::path& file) {
    if (!options_.use_config) return nullptr;
    if (options_.config) return explicit_;
    const std::optional<fs::path> path = FindConfigFor(file);
    return path ? Load(*path) : nullptr;
  }

 private:
  const Config* Load(const fs::path& path) {
    const fs::path key = fs::weakly_canonical(path);
    if (auto it = configs_.find(key); it != configs_.end()) return &it->second;
    ConfigResult result = LoadConfig(path, sources_);
    if (!result.diagnostics.empty()) {
      FileReport report;
      const FileId id = result.diagnostics.front().range.file;
      report.file = id != kNoFile ? &sources_.Get(id) : &sources_.Add(path.string(), "");
      for (Diagnostic& diagnostic : result.diagnostics) {
        if (!diagnostic.range.Valid()) diagnostic.range = {report.file->Id(), 0, 0};
      }
      report.diagnostics = std::move(result.diagnostics);
      run_.report.files.push_back(std::move(report));
    }
    return &configs_.emplace(key, std::move(result.config)).first->second;
  }

  const CheckOptions& options_;
  SourceManager& sources_;
  CheckRun& run_;
  const Config* explicit_ = nullptr;
  std::map<fs::path, Config> configs_;  // node-based: pointers stay valid
};

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

}  // namespace

CheckRun RunCheck(const CheckOptions& options) {
  CheckRun run;
  run.report.sources = run.sources.get();
  SourceManager& sources = *run.sources;

  InputFileList inputs = CollectInputFiles(options.paths);
  run.usage_errors = std::move(inputs.errors);

  ConfigCache configs(options, sources, run);
  std::map<fs::path, const SourceFile*> commons;
  std::vector<FileJob> jobs;
  std::vector<fs::path> explicit_files(options.paths.begin(), options.paths.end());
  for (const fs::path& path : inputs.files) {
    FileJob job;
    job.path = path;
    job.config = configs.For(path);
    const bool named =
        std::find(explicit_files.begin(), explicit_files.end(), path) != explicit_files.end();
    // Config globs are relative to the config's (absolute) directory.
    if (!named && job.config != nullptr && !IsIncluded(*job.config, fs::absolute(path))) continue;
    job.common = CommonFor(path, options, commons, sources, run);
    jobs.push_back(std::move(job));
  }
  for (FileJob& job : jobs) {
    if (job.common == nullptr) continue;
    job.common_checked_separately =
        std::any_of(jobs.begin(), jobs.end(), [&](const FileJob& other) {
          return fs::weakly_canonical(other.path) == fs::weakly_canonical(job.common->Name());
        });
  }

  std::vector<FileReport> reports(jobs.size());
  ParallelFor(jobs.size(), options.jobs,
              [&](size_t i) { reports[i] = CheckFile(jobs[i], options, sources); });
  // Programs link once both stages are checked (before renders, whose findings
  // must not stop a link).
  for (const auto& [vertex, fragment] : FindPrograms(jobs, options)) {
    LinkProgram(jobs[vertex], jobs[fragment], options, sources, reports[vertex], reports[fragment]);
  }
  // Each render forks a child. Forking while other threads run can leave the child
  // waiting forever on a lock one of them held, so renders run here, one at a
  // time, once the parallel part has ended (llvmpipe draws on several threads itself).
  if (options.render) {
    for (size_t i = 0; i < jobs.size(); ++i)
      RenderCheckedFile(jobs[i], options, sources, reports[i]);
  }

  for (size_t i = 0; i < jobs.size(); ++i) {
    const Config* config = jobs[i].config;
    Severity fail_on = config != nullptr ? config->fail_on : Severity::kError;
    if (options.fail_on) fail_on = *options.fail_on;
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
