#include "driver/port/fix_run.h"

#include "driver/check_projects.h"
#include "driver/port/file_lock.h"
#include "driver/port/output_files.h"
#include "driver/port/port_report.h"
#include "driver/project/fix_document.h"

namespace shaderport::driver {
namespace {

namespace fs = std::filesystem;

FixRunOptions InFixMode(FixRunOptions options) {
  options.port.mode = rule::PortMode::kFix;
  return options;
}

void Write(const fs::path& path, const std::string& text, FixRun& run) {
  std::string error = file_io::WriteFileAtomically(path, text);
  if (!error.empty()) run.write_errors.push_back(std::move(error));
}

// Sends one fixed file where the options say. A byte order mark the input began
// with is written back: fix changes only what rules fix.
void Emit(const PortResult& result, const fs::path& path, const FixRunOptions& options,
          FixRun& run) {
  if (result.read_failed) {
    run.unreadable = true;
    return;
  }
  // Fixes that did not settle are not written anywhere, not even to standard output:
  // a format-on-save editor keeps its text (the findings name the rules).
  if (!result.converged) {
    run.unsettled = true;
    return;
  }
  if (options.destination == FixDestination::kDiff) {
    run.standard_output += UnifiedDiff(result.file->Text(), result.text, path.string());
    return;
  }
  const std::string text = (result.byte_order_mark ? "\xEF\xBB\xBF" : "") + result.text;
  if (options.destination == FixDestination::kInPlace) {
    if (result.Changed()) Write(path, text, run);
  } else if (options.destination == FixDestination::kFile) {
    Write(options.output, text, run);
  } else {
    run.standard_output += text;
  }
}

// A ShaderToy JSON document: the fixed code goes back into its code strings only.
// The passes' findings, and the document's own problems as a result of their own.
void FixProjectDocument(const fs::path& path, InputText input, const FixRunOptions& options,
                        SourceManager& sources, FixRun& run) {
  project::FixedDocument fixed =
      project::FixDocument(path, std::move(input), options.port, sources);
  if (fixed.read_failed) {
    run.unreadable = true;
  } else if (!AllConverged(fixed.passes)) {
    run.unsettled = true;
  } else {
    PortResult whole;
    whole.file = fixed.document;
    whole.text = fixed.text;
    Emit(whole, path, options, run);
  }
  if (!fixed.problems.empty()) {
    PortResult problems;
    problems.file = fixed.document;
    problems.read_failed = true;
    problems.diagnostics = std::move(fixed.problems);
    run.results.push_back(std::move(problems));
  }
  for (PortResult& pass : fixed.passes) run.results.push_back(std::move(pass));
}

}  // namespace

FixRun RunFix(const std::vector<InputFile>& inputs, const FixRunOptions& fix_options,
              SourceManager& sources) {
  const FixRunOptions options = InFixMode(fix_options);
  FixRun run;
  for (const InputFile& input : inputs) {
    // Held from reading to writing: a concurrent `fix -i` of the same file
    // waits, then reads (and leaves alone) the text written here.
    const FileUpdateLock lock = options.destination == FixDestination::kInPlace
                                    ? FileUpdateLock(input.path)
                                    : FileUpdateLock();
    if (IsProjectDocument(input.path)) {
      FixProjectDocument(input.path, ReadInputFile(input.path), options, sources, run);
      continue;
    }
    run.results.push_back(PortFile(input.path, OptionsFor(options.port, input), sources));
    Emit(run.results.back(), input.path, options, run);
  }
  return run;
}

FixRun RunFixOnText(const fs::path& name, InputText input, const FixRunOptions& fix_options,
                    SourceManager& sources) {
  const FixRunOptions options = InFixMode(fix_options);
  FixRun run;
  if (IsProjectDocument(name)) {
    FixProjectDocument(name, std::move(input), options, sources, run);
  } else {
    run.results.push_back(PortInput(name, std::move(input), options.port, sources));
    Emit(run.results.back(), name, options, run);
  }
  return run;
}

FixRun ReturnUnchanged(const std::string& text, const FixRunOptions& options) {
  FixRun run;
  if (options.destination == FixDestination::kDiff) return run;
  if (options.destination == FixDestination::kFile) {
    Write(options.output, text, run);
  } else {
    run.standard_output = text;
  }
  return run;
}

}  // namespace shaderport::driver
