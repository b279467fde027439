// Turns the paths a user gives into the list of shader files to process. Every
// command that takes paths (check, fix, port, report, summary) walks them here.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "driver/dialect.h"

namespace shaderport::driver {

// Extensions picked up when a directory is walked.
bool IsShaderExtension(const std::filesystem::path& path);

// "PATH: no such file or directory" (or why it cannot be reached, e.g. a symbolic
// link loop) when `path` names nothing, "PATH: no file matches this pattern" when
// it is a pattern (`*`, `?`, `[`) the shell left as written because nothing
// matched; "" when it exists. The message every command gives for a missing path.
std::string MissingPathError(const std::filesystem::path& path);

// True when `path` does not exist and holds `*`, `?` or `[`: a glob that matched
// nothing.
bool IsUnmatchedPattern(const std::filesystem::path& path);

struct InputFile {
  std::filesystem::path path;  // to open: the argument, or the argument joined with `relative`
  // Where the file sits under the argument it came from: the path below a directory
  // argument, or the argument itself (normalised) for a file named directly. This is
  // the layout `port --out-dir` and the like keep.
  std::filesystem::path relative;
  bool named = false;  // named on the command line, not found by walking
  // What the file's .shaderport.toml [[files]] entries say about it (fix, port: the
  // same overrides `check` applies; SelectConfiguredInputs fills them in).
  std::optional<Dialect> dialect{};
  std::optional<model::Stage> stage{};
};

struct InputSet {
  std::vector<InputFile> files;     // in argument order, each directory's files sorted
  std::vector<std::string> errors;  // paths that do not exist, unreadable directories
  size_t dropped = 0;               // files the filter left out
  // Unmatched patterns (IsUnmatchedPattern), as MissingPathError words them; not
  // in `errors`: an empty run may be accepted (check --allow-empty).
  std::vector<std::string> unmatched;
};

// Decides whether a file is kept (the include and exclude globs of its
// .shaderport.toml).
using KeepWalkedFile = std::function<bool(const std::filesystem::path& file)>;

// Files named directly are taken whatever their extension; directories are walked
// recursively for shader extensions, skipping hidden directories. A file reached
// twice is listed once, where it is first reached. `keep` filters the files found
// in directories, and the files named directly too when `filter_named` is set (as
// ruff's --force-exclude: pre-commit names every staged file).
InputSet WalkInputs(const std::vector<std::filesystem::path>& paths,
                    const KeepWalkedFile& keep = nullptr, bool filter_named = false);

struct InputFileList {
  std::vector<std::filesystem::path> files;  // WalkInputs' paths, nothing dropped
  std::vector<std::string> errors;
};

// WalkInputs without a filter, paths only.
InputFileList CollectInputFiles(const std::vector<std::filesystem::path>& paths);

}  // namespace shaderport::driver
