#include "driver/port/port_project_files.h"

#include <set>
#include <string>

#include "driver/check_projects.h"
#include "driver/dialect.h"
#include "driver/port/output_files.h"
#include "driver/project/folder_project.h"
#include "driver/project/port_document.h"
#include "driver/read_input.h"

namespace shaderport::driver {
namespace {

namespace fs = std::filesystem;

struct ProgramInput {
  InputFile input;
  PortResult result;
  bool vertex() const { return result.output_stage == model::Stage::kVertex; }
};

// Pages of shaders that are not ShaderToy passes: a vertex and a fragment shader
// given together (or, among more files, with the same directory and name) make one
// page; the others a page each. Appends (input, page) in input order.
void ProgramPages(const std::vector<ProgramInput>& programs, std::vector<InputFile>& inputs,
                  std::vector<project::DocumentOutput>& pages, std::vector<bool>& compiles) {
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
    pages.push_back(project::ProgramPage(vertex ? &vertex->result : nullptr,
                                         fragment ? &fragment->result : nullptr));
    compiles.push_back((vertex == nullptr || vertex->result.validated) &&
                       (fragment == nullptr || fragment->result.validated));
  }
}

// The files one ported document gives, in the layout `options` asks for.
std::vector<project::DocumentOutput> OutputsOf(const project::PortedDocument& document,
                                               PortLayout layout) {
  switch (layout) {
    case PortLayout::kPage:
      return project::PageOutputs(document);
    case PortLayout::kFolder:
      return project::FolderOutputs(document);
    case PortLayout::kShaders:
      break;
  }
  return project::ShaderOutputs(document);
}

// What the inputs give, in order: each text and where it goes ("" for standard output).
struct PlannedOutputs {
  std::vector<fs::path> inputs;
  std::vector<fs::path> targets;
  std::vector<std::string> texts;
};

}  // namespace

void PortProjectFiles(const std::vector<InputFile>& inputs, const PortRunOptions& options,
                      SourceManager& sources, PortRun& run) {
  const PortOptions& port = options.port;
  std::vector<project::PortedDocument> documents;
  PlannedOutputs planned;
  std::set<fs::path> folders_done;
  std::vector<ProgramInput> programs;  // pages of shaders that are not ShaderToy's
  for (const InputFile& input : inputs) {
    // A tab file of a project folder stands for the whole folder, ported once.
    const fs::path folder = project::ProjectFolderOf(input.path);
    fs::path relative = input.relative;
    if (!folder.empty()) {
      if (!folders_done.insert(folder).second) continue;
      documents.push_back(project::PortFolder(folder, port, sources));
      relative = relative.parent_path().empty() ? folder.filename() : relative.parent_path();
    } else if (IsProjectDocument(input.path)) {
      documents.push_back(project::PortDocument(input.path, ReadInputFile(input.path), port,
                                                sources, options.layout != PortLayout::kFolder));
    } else {
      InputText text = ReadInputFile(input.path);
      DetectedKind kind = DetectKind(text.text ? std::string_view(*text.text) : "", input.path);
      if (port.dialect) kind.dialect = *port.dialect;
      if (options.layout == PortLayout::kPage && text.text && kind.dialect != Dialect::kShaderToy) {
        programs.push_back({input, PortInput(input.path, std::move(text), port, sources)});
        continue;
      }
      documents.push_back(project::PortSinglePass(input.path, std::move(text), port, sources));
    }
    // A pass whose fixes did not settle: nothing of its document is written (exit 3).
    if (!documents.back().Findings().converged) {
      run.unsettled = true;
      continue;
    }
    // A folder is the project as written; a port that does not compile is not written.
    if (options.layout != PortLayout::kFolder && !options.write_invalid &&
        !documents.back().read_failed && !documents.back().Validated()) {
      run.unwritten.push_back(input.path);
      continue;
    }
    const std::vector<project::DocumentOutput> outputs =
        OutputsOf(documents.back(), options.layout);
    if (outputs.size() > 1 && options.out_dir.empty()) {
      run.usage_error =
          input.path.string() + " gives " + std::to_string(outputs.size()) +
          " files: use --out-dir" +
          (options.layout == PortLayout::kShaders ? " (or --emit html for one page)" : "");
      return;
    }
    for (const project::DocumentOutput& output : outputs) {
      fs::path target;
      if (!options.out_dir.empty()) {
        // doc.json -> OUT/doc/image.frag, OUT/doc.html (or OUT/doc/<id>.html).
        const fs::path base = folder.empty()
                                  ? OutDirPath(options.out_dir, relative, "")
                                  : OutDirPath(options.out_dir, relative / "x", "").parent_path();
        if (options.layout == PortLayout::kPage && output.relative.empty()) {
          target = base.string() + ".html";
        } else {
          target = base / output.relative;
        }
      } else if (!options.output.empty()) {
        target = options.output;
      }
      planned.inputs.push_back(input.path);
      planned.targets.push_back(target);
      planned.texts.push_back(output.text);
    }
  }
  std::vector<InputFile> program_inputs;
  std::vector<project::DocumentOutput> program_pages;
  std::vector<bool> program_pages_valid;
  ProgramPages(programs, program_inputs, program_pages, program_pages_valid);
  for (size_t i = 0; i < program_pages.size(); ++i) {
    if (!options.write_invalid && !program_pages_valid[i]) {
      run.unwritten.push_back(program_inputs[i].path);
      continue;
    }
    // geometry.vert + position.frag -> OUT/position.html (named after the fragment).
    planned.inputs.push_back(program_inputs[i].path);
    const fs::path base = OutDirPath(options.out_dir, program_inputs[i].relative, "");
    planned.targets.push_back(options.out_dir.empty() ? options.output
                                                      : fs::path(base.string() + ".html"));
    planned.texts.push_back(std::move(program_pages[i].text));
  }
  for (const project::PortedDocument& document : documents) {
    run.results.push_back(document.Findings());
  }
  for (ProgramInput& program : programs) {
    if (!program.result.converged) run.unsettled = true;
    run.results.push_back(std::move(program.result));
  }
  if (!options.output.empty() && planned.texts.size() > 1) {
    run.usage_error = "-o takes one page, and the inputs give " +
                      std::to_string(planned.texts.size()) + " (use --out-dir)";
    return;
  }
  if (!options.out_dir.empty()) {
    const std::string clash = OutputClash(planned.inputs, planned.targets);
    if (!clash.empty()) {
      run.usage_error = clash + "; nothing was written";
      return;
    }
  }
  for (size_t i = 0; i < planned.texts.size(); ++i) {
    if (planned.targets[i].empty()) {
      run.standard_output += planned.texts[i];
    } else if (std::string why = WriteOutput(planned.targets[i], planned.texts[i]); !why.empty()) {
      run.write_errors.push_back(std::move(why));
    }
  }
}

}  // namespace shaderport::driver
