// What `shaderport check` found, file by file: the input of every output format.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "diag/diagnostic.h"
#include "report/docs_links.h"
#include "source/source_file.h"
#include "source/source_manager.h"

namespace shaderport {

// What an entry of a report stands for, so that the summary counts what was checked.
enum class FileRole {
  kShader,  // a shader file
  kTab,     // a tab (pass) of a ShaderToy project; FileReport::project names the project
  kInput,   // findings about an input that is not itself checked: a .shaderport.toml,
            // a project document's own problems
};

// One part of what a file was decided to be, and why (driver/file_decision.h):
// {"harness", "raymarch-blog", "uses uv without declaring it"}.
struct DecisionPart {
  std::string part;
  std::string value;
  std::string because;
};

struct FileReport {
  const SourceFile* file = nullptr;
  std::string dialect;  // "shadertoy", "webgl1", "webgl2" ("" when unknown)
  std::string stage;    // "vertex", "fragment" ("" when unknown)
  // Sorted by position. A range may point into another file of the SourceManager
  // (e.g. a ShaderToy Common file); printers show the file the range is in.
  DiagnosticList diagnostics;
  // The least severe diagnostic that fails the check for this file (its config's
  // fail-on or --fail-on), so that the run can be judged again after a baseline.
  Severity fail_on = Severity::kError;
  FileRole role = FileRole::kShader;
  std::string project{};  // kTab: the project (document and index, or folder) it belongs to
  std::string
      harness{};  // the host that completes the code ("shadertoy", "raymarch-blog"; "": none)
  std::string target{};  // the WebGL context it is checked for: "webgl1", "webgl2" ("": unknown)
  // ShaderToy code: the sampler type of iChannel0..3 as checked ("2d 2d cube 2d"; "": none).
  std::string channels{};
  std::vector<DecisionPart> decision{};  // filled for `explain-file` only
};

struct CheckReport {
  std::vector<FileReport> files;
  const SourceManager* sources = nullptr;
};

// Settings shared by the output formats; the CLI fills them in.
struct ReportOptions {
  std::string tool_version = "0.0.0";
  // Absolute directory that paths are made relative to (SARIF's %SRCROOT%, the
  // GitHub annotation paths). Empty: paths are printed as the files are named.
  std::string base_directory;
  std::string information_uri{kRepositoryUri};  // SARIF tool.driver.informationUri
  // Rule ids with their own section in docs/rules.md (SARIF helpUri points there),
  // sorted; other ids point at that page's table of every id.
  std::vector<std::string> rules_with_sections;
  bool color = false;        // text only: ANSI colours (the CLI decides: TTY, NO_COLOR)
  bool summary_line = true;  // text only: end with the "N errors, ..." line (check -q: not)
};

struct ReportSummary {
  size_t errors = 0;
  size_t warnings = 0;
  size_t notes = 0;
  size_t files_with_problems = 0;  // entries (files, tabs) with a diagnostic of any severity
  size_t files_checked = 0;        // shader files and project tabs: what was checked
  size_t tabs_checked = 0;         // of those, tabs of ShaderToy projects
  size_t projects = 0;             // the projects those tabs belong to
  size_t fixable = 0;              // diagnostics `shaderport fix` repairs (IsFixable)
};

ReportSummary Summarize(const CheckReport& report);

// True when some diagnostic is at or above its file's fail-on level.
bool ReportFails(const CheckReport& report);

// Puts files in path order and each file's diagnostics in position order
// (file, offset, end, then rule id), so that every format is deterministic.
void SortReport(CheckReport& report);

}  // namespace shaderport
