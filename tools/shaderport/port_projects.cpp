#include "port_projects.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <set>

#include "cli_errors.h"
#include "commands.h"
#include "driver/check_projects.h"
#include "driver/dialect.h"
#include "driver/port/output_files.h"
#include "driver/port/port_report.h"
#include "driver/project/folder_project.h"
#include "driver/project/port_document.h"

namespace shaderport::cli {
namespace fs = std::filesystem;

namespace {

struct ProgramInput {
  driver::InputFile input;
  driver::PortResult result;
  bool vertex() const { return result.output_stage == model::Stage::kVertex; }
};

// Pages of shaders that are not ShaderToy passes: a vertex and a fragment shader
// given together (or, among more files, with the same directory and name) make one
// page; the others a page each. Appends (input, page) in input order.
void ProgramPages(const std::vector<ProgramInput>& programs, std::vector<driver::InputFile>& inputs,
                  std::vector<driver::project::DocumentOutput>& pages,
                  std::vector<bool>& compiles) {
  std::vector<int> partner(programs.size(), -1);
  const auto pair = [&](size_t a, size_t b) {
    partner[a] = static_cast<int>(b);
    partner[b] = static_cast<int>(a);
  };
  if (programs.size() == 2 && programs[0].vertex() != programs[1].vertex()) pair(0, 1);
  for (size_t a = 0; a < programs.size() && programs.size() > 2; ++a) {
    for (size_t b = 0; b < programs.size(); ++b) {
      const fs::path& x = programs[a].input.path;
      const fs::path& y = programs[b].input.path;
      if (partner[a] < 0 && partner[b] < 0 && programs[a].vertex() && !programs[b].vertex() &&
          x.parent_path() == y.parent_path() && x.stem() == y.stem()) {
        pair(a, b);
      }
    }
  }
  for (size_t i = 0; i < programs.size(); ++i) {
    const int other = partner[i];
    if (other >= 0 && programs[i].vertex()) continue;  // written with its fragment shader
    const ProgramInput* vertex = programs[i].vertex() ? &programs[i] : nullptr;
    const ProgramInput* fragment = programs[i].vertex() ? nullptr : &programs[i];
    if (other >= 0) vertex = &programs[static_cast<size_t>(other)];
    inputs.push_back(programs[i].input);
    pages.push_back(driver::project::ProgramPage(vertex ? &vertex->result : nullptr,
                                                 fragment ? &fragment->result : nullptr));
    compiles.push_back((vertex == nullptr || vertex->result.validated) &&
                       (fragment == nullptr || fragment->result.validated));
  }
}

}  // namespace

int PortProjectInputs(const std::vector<driver::InputFile>& inputs,
                      const driver::PortOptions& options, const ProjectPortTargets& targets,
                      SourceManager& sources) {
  std::vector<driver::project::PortedDocument> documents;
  std::vector<fs::path> input_paths;
  std::vector<fs::path> target_paths;
  std::vector<std::string> texts;
  int exit_code = kExitOk;
  std::set<fs::path> folders_done;
  std::vector<ProgramInput> programs;  // --emit html of shaders that are not ShaderToy's
  std::vector<fs::path> unwritten;     // ported, but a pass does not compile
  for (const driver::InputFile& input : inputs) {
    // A tab file of a project folder stands for the whole folder, ported once.
    const fs::path folder = driver::project::ProjectFolderOf(input.path);
    fs::path relative = input.relative;
    if (!folder.empty()) {
      if (!folders_done.insert(folder).second) continue;
      documents.push_back(driver::project::PortFolder(folder, options, sources));
      relative = relative.parent_path().empty() ? folder.filename() : relative.parent_path();
    } else if (driver::IsProjectDocument(input.path)) {
      documents.push_back(
          driver::project::PortDocument(input.path, driver::ReadInputFile(input.path), options,
                                        sources, targets.emit != ProjectEmit::kFolder));
    } else {
      driver::InputText text = driver::ReadInputFile(input.path);
      driver::DetectedKind kind =
          driver::DetectKind(text.text ? std::string_view(*text.text) : "", input.path);
      if (options.dialect) kind.dialect = *options.dialect;
      if (targets.emit == ProjectEmit::kHtml && text.text &&
          kind.dialect != driver::Dialect::kShaderToy) {
        programs.push_back(
            {input, driver::PortInput(input.path, std::move(text), options, sources)});
        continue;
      }
      documents.push_back(
          driver::project::PortSinglePass(input.path, std::move(text), options, sources));
    }
    // A pass whose fixes did not settle: nothing of its document is written (exit 3).
    if (!documents.back().Findings().converged) {
      exit_code = kExitInternal;
      continue;
    }
    // A folder is the project as written; a port that does not compile is not written.
    if (targets.emit != ProjectEmit::kFolder && !targets.write_invalid &&
        !documents.back().read_failed && !documents.back().Validated()) {
      unwritten.push_back(input.path);
      continue;
    }
    const auto outputs =
        targets.emit == ProjectEmit::kHtml     ? driver::project::PageOutputs(documents.back())
        : targets.emit == ProjectEmit::kFolder ? driver::project::FolderOutputs(documents.back())
                                               : driver::project::ShaderOutputs(documents.back());
    const bool single = outputs.size() == 1;
    if (!single && targets.out_dir.empty() && !outputs.empty()) {
      return UsageError(
          input.path.string() + " gives " + std::to_string(outputs.size()) +
          " files: use --out-dir" +
          (targets.emit == ProjectEmit::kShaders ? " (or --emit html for one page)" : ""));
    }
    for (const driver::project::DocumentOutput& output : outputs) {
      fs::path target;
      if (!targets.out_dir.empty()) {
        // doc.json -> OUT/doc/image.frag, OUT/doc.html (or OUT/doc/<id>.html).
        const fs::path base =
            folder.empty() ? driver::OutDirPath(targets.out_dir, relative, "")
                           : driver::OutDirPath(targets.out_dir, relative / "x", "").parent_path();
        if (targets.emit == ProjectEmit::kHtml && output.relative.empty()) {
          target = base.string() + ".html";
        } else {
          target = base / output.relative;
        }
      } else if (!targets.output.empty()) {
        target = targets.output;
      }
      input_paths.push_back(input.path);
      target_paths.push_back(target);
      texts.push_back(output.text);
    }
  }
  std::vector<driver::InputFile> program_inputs;
  std::vector<driver::project::DocumentOutput> program_pages;
  std::vector<bool> program_pages_valid;
  ProgramPages(programs, program_inputs, program_pages, program_pages_valid);
  for (size_t i = 0; i < program_pages.size(); ++i) {
    if (!targets.write_invalid && !program_pages_valid[i]) {
      unwritten.push_back(program_inputs[i].path);
      continue;
    }
    // geometry.vert + position.frag -> OUT/position.html (named after the fragment).
    input_paths.push_back(program_inputs[i].path);
    const fs::path base = driver::OutDirPath(targets.out_dir, program_inputs[i].relative, "");
    target_paths.push_back(targets.out_dir.empty() ? fs::path(targets.output)
                                                   : fs::path(base.string() + ".html"));
    texts.push_back(std::move(program_pages[i].text));
  }
  if (!targets.output.empty() && texts.size() > 1) {
    return UsageError("-o takes one page, and the inputs give " + std::to_string(texts.size()) +
                      " (use --out-dir)");
  }
  if (!targets.out_dir.empty()) {
    const std::string clash = driver::OutputClash(input_paths, target_paths);
    if (!clash.empty()) {
      return UsageError(clash + "; nothing was written");
    }
  }
  for (size_t i = 0; i < texts.size(); ++i) {
    if (target_paths[i].empty()) {
      std::fwrite(texts[i].data(), 1, texts[i].size(), stdout);
      continue;
    }
    std::error_code error;
    if (target_paths[i].has_parent_path())
      fs::create_directories(target_paths[i].parent_path(), error);
    const std::string why = file_io::WriteFileAtomically(target_paths[i], texts[i]);
    if (!why.empty()) {
      PrintError(why);
      exit_code = kExitInternal;
    }
  }
  std::vector<driver::PortResult> findings;
  for (const auto& document : documents) findings.push_back(document.Findings());
  for (const ProgramInput& program : programs) {
    findings.push_back(program.result);
    if (!program.result.converged) exit_code = kExitInternal;
  }
  if (!driver::HasFindings(findings)) return exit_code;
  const bool color = ::isatty(STDERR_FILENO) != 0 && std::getenv("NO_COLOR") == nullptr;
  std::fputs(driver::FormatPortFindings(findings, sources, color).c_str(), stderr);
  PrintUnwritten(unwritten);
  return std::max(exit_code, driver::FailsAt(findings, targets.fail_on) ? kExitFindings : kExitOk);
}

}  // namespace shaderport::cli
