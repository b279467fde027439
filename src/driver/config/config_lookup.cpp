#include "driver/config/config_lookup.h"

#include "driver/config/find_config.h"

namespace shaderport::driver {

namespace fs = std::filesystem;

ConfigLookup::ConfigLookup(bool use_config, const std::optional<fs::path>& explicit_config,
                           SourceManager& sources)
    : use_config_(use_config), explicit_path_(explicit_config), sources_(sources) {
  std::error_code error;
  working_directory_ = fs::current_path(error);
  if (!use_config_ || !explicit_path_) return;
  const fs::file_status status = fs::status(*explicit_path_, error);
  if (status.type() == fs::file_type::not_found) {
    explicit_error_ = "--config " + explicit_path_->string() + ": no such file";
  } else if (!error && fs::is_directory(status)) {
    explicit_error_ = "--config " + explicit_path_->string() + ": is a directory, not a file";
  } else {
    explicit_ = Load(*explicit_path_);  // unreadable or malformed: findings in the file
  }
}

fs::path ConfigLookup::Absolute(const fs::path& file) const {
  return file.is_absolute() || working_directory_.empty() ? file : working_directory_ / file;
}

const Config* ConfigLookup::For(const fs::path& file) {
  if (!use_config_) return nullptr;
  if (explicit_path_) return explicit_;
  const fs::path directory = Absolute(file).lexically_normal().parent_path();
  if (auto it = by_directory_.find(directory); it != by_directory_.end()) return it->second;
  const std::optional<fs::path> path = FindConfigFor(file);
  const Config* config = path ? Load(*path) : nullptr;
  // A directory named as a file finds its config from itself: not memoised.
  std::error_code error;
  if (!fs::is_directory(file, error)) by_directory_.emplace(directory, config);
  return config;
}

bool ConfigLookup::Includes(const fs::path& file) {
  const Config* config = For(file);
  // Config globs are relative to the config's (absolute) directory.
  return config == nullptr || IsIncluded(*config, Absolute(file));
}

std::vector<FileReport> ConfigLookup::TakeProblems() { return std::move(problems_); }

const Config* ConfigLookup::Load(const fs::path& path) {
  std::error_code error;
  fs::path key = fs::weakly_canonical(path, error);
  if (error) key = Absolute(path).lexically_normal();
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
    problems_.push_back(std::move(report));
  }
  return &configs_.emplace(key, std::move(result.config)).first->second;
}

}  // namespace shaderport::driver
