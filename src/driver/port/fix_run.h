// `shaderport fix` over the selected inputs (input_selection.h) or a text read
// elsewhere (standard input): the safe fixes that keep each file's dialect, the
// result written in place, to one file, or kept for standard output as text or a
// diff. The caller prints.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "driver/input_files.h"
#include "driver/port/port_file.h"
#include "driver/read_input.h"
#include "source/source_manager.h"

namespace shaderport::driver {

// Where a fixed file goes.
enum class FixDestination {
  kStandardOutput,  // the fixed text (the default)
  kDiff,            // --diff: a unified diff from the original
  kInPlace,         // -i: the file itself, when it changed
  kFile,            // -o: `FixRunOptions::output`
};

struct FixRunOptions {
  PortOptions port;  // --dialect, --channel, --stage (the mode is fix's)
  FixDestination destination = FixDestination::kStandardOutput;
  std::filesystem::path output;  // kFile
};

struct FixRun {
  // Every file's findings; a JSON document's own problems are a result of their own.
  std::vector<PortResult> results;
  std::string standard_output;            // fixed texts or diffs
  std::vector<std::string> write_errors;  // why a file could not be written
  bool unreadable = false;  // some input could not be read or is not a project (exit 1)
  bool unsettled = false;   // some fixes did not settle: that file was not written (exit 3)
};

// Fixes `inputs` (as SelectConfiguredInputs gives them) one after another; with
// kInPlace each file is locked from reading until its new text is in.
FixRun RunFix(const std::vector<InputFile>& inputs, const FixRunOptions& options,
              SourceManager& sources);

// Fixes `input`, read by the caller, as the file `name`, which need not exist.
FixRun RunFixOnText(const std::filesystem::path& name, InputText input,
                    const FixRunOptions& options, SourceManager& sources);

// Text whose name the config excludes goes back unchanged, as a named file would be
// left alone (ruff): to -o or standard output, and no diff.
FixRun ReturnUnchanged(const std::string& text, const FixRunOptions& options);

}  // namespace shaderport::driver
