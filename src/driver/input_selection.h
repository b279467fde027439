// The one walk of the paths `check`, `fix` and `port` take, together with the
// .shaderport.toml lookup: which files run, and what their configs say about them.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "driver/config/config_lookup.h"
#include "driver/input_files.h"
#include "report/check_report.h"
#include "source/source_manager.h"

namespace shaderport::driver {

struct InputSelectionOptions {
  std::vector<std::filesystem::path> paths;
  // --stdin-filename: instead of `paths`, the one file standard input stands for (it
  // need not exist); it counts as a file named on the command line.
  std::optional<std::filesystem::path> stdin_name;
  std::optional<std::filesystem::path> config;  // --config: instead of searching upward
  bool use_config = true;                       // --no-config
  bool force_exclude = true;  // the globs apply to named files too (--no-force-exclude)
};

struct InputSelection {
  std::vector<InputFile> files;        // in argument order, each directory's files sorted
  std::vector<std::string> errors;     // an unusable --config (nothing is walked), missing paths
  std::vector<std::string> unmatched;  // patterns the shell left unexpanded (InputSet)
  size_t dropped = 0;                  // files the include/exclude globs left out
  // Problems of the config files read while walking, pointing into the lookup's sources.
  std::vector<FileReport> config_problems;

  // The paths held no shader file at all, not even an excluded one: the caller
  // decides whether an empty run is an error.
  bool FoundNothing() const { return files.empty() && dropped == 0; }
  // Some config problem is an error (fix and port then exit 1).
  bool ConfigFailed() const;
};

// Walks with the caller's lookup, made from `options.use_config` and `options.config`,
// which keeps the configs for the run (check's jobs).
// Configs first read after this (a named file's, with --no-force-exclude) report their
// problems through the lookup, not here.
InputSelection SelectInputs(const InputSelectionOptions& options, ConfigLookup& configs);

// fix and port: the selection with a lookup of its own, each file given its
// [[files]] dialect and stage, the config problems kept apart from the findings.
struct ConfiguredInputs {
  std::unique_ptr<SourceManager> config_sources = std::make_unique<SourceManager>();
  InputSelection selection;
};
ConfiguredInputs SelectConfiguredInputs(const InputSelectionOptions& options);

}  // namespace shaderport::driver
