// Which .shaderport.toml governs each input file: found by walking up from the
// file (or the one given with --config), parsed once and kept for the run.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "driver/config/config.h"
#include "report/check_report.h"
#include "source/source_manager.h"

namespace shaderport::driver {

// Not thread-safe: configs are looked up before the parallel part of a run, so
// that every job sees a finished Config.
class ConfigLookup {
 public:
  // `use_config` false (--no-config): no file governs anything. `explicit_config`
  // (--config): that file governs every input.
  ConfigLookup(bool use_config, const std::optional<std::filesystem::path>& explicit_config,
               SourceManager& sources);

  // Why the file given with --config cannot be used (it does not exist or is not
  // a file), or "" when it can: a usage error, not a finding.
  const std::string& ExplicitConfigError() const { return explicit_error_; }

  // nullptr when no config applies.
  const Config* For(const std::filesystem::path& file);

  // The include and exclude globs of the file's config (true when there is none).
  bool Includes(const std::filesystem::path& file);

  // One report per config file that had problems (syntax errors, unknown keys),
  // its diagnostics pointing into it; the lookup forgets them.
  std::vector<FileReport> TakeProblems();

 private:
  const Config* Load(const std::filesystem::path& path);
  std::filesystem::path Absolute(const std::filesystem::path& file) const;

  bool use_config_;
  std::optional<std::filesystem::path> explicit_path_;
  SourceManager& sources_;
  const Config* explicit_ = nullptr;
  std::string explicit_error_;
  std::map<std::filesystem::path, Config> configs_;  // node-based: pointers stay valid
  std::vector<FileReport> problems_;
  // Every file of a directory has the same config: the upward search (a stat
  // per level) runs once per directory, which matters for 10,000-file runs.
  std::map<std::filesystem::path, const Config*> by_directory_;
  std::filesystem::path working_directory_;  // read once: getcwd per file adds up
};

}  // namespace shaderport::driver
