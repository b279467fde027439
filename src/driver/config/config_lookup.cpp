#include "driver/config/config_lookup.h"

#include "driver/config/find_config.h"

namespace shaderport::driver {

namespace fs = std::filesystem;

ConfigLookup::ConfigLookup(bool use_config, const std::optional<fs::path>& explicit_config,
                           SourceManager& sources)
    : use_config_(use_config), explicit_path_(explicit_config), sources_(sources) {
  if (use_config_ && explicit_path_) explicit_ = Load(*explicit_path_);
}

const Config* ConfigLookup::For(const fs::path& file) {
  if (!use_config_) return nullptr;
  if (explicit_path_) return explicit_;
  const std::optional<fs::path> path = FindConfigFor(file);
  return path ? Load(*path) : nullptr;
}

bool ConfigLookup::Includes(const fs::path& file) {
  const Config* config = For(file);
  // Config globs are relative to the config's (absolute) directory.
  return config == nullptr || IsIncluded(*config, fs::absolute(file));
}

std::vector<FileReport> ConfigLookup::TakeProblems() { return std::move(problems_); }

const Config* ConfigLookup::Load(const fs::path& path) {
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
    problems_.push_back(std::move(report));
  }
  return &configs_.emplace(key, std::move(result.config)).first->second;
}

}  // namespace shaderport::driver
