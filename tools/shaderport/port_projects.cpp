#include "port_projects.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <set>

#include "commands.h"
#include "driver/check_projects.h"
#include "driver/port/output_files.h"
#include "driver/port/port_report.h"
#include "driver/project/folder_project.h"
#include "driver/project/port_document.h"

namespace shaderport::cli {
namespace fs = std::filesystem;

fs::path InputProjectFolder(const fs::path& file) { return driver::project::ProjectFolderOf(file); }

int PortProjectInputs(const std::vector<driver::InputFile>& inputs,
                      const driver::PortOptions& options, const ProjectPortTargets& targets,
                      SourceManager& sources) {
  std::vector<driver::project::PortedDocument> documents;
  std::vector<fs::path> input_paths;
  std::vector<fs::path> target_paths;
  std::vector<std::string> texts;
  int exit_code = kExitOk;
  std::set<fs::path> folders_done;
  for (const driver::InputFile& input : inputs) {
    // A tab file of a project folder stands for the whole folder, ported once.
    const fs::path folder = InputProjectFolder(input.path);
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
      documents.push_back(driver::project::PortSinglePass(
          input.path, driver::ReadInputFile(input.path), options, sources));
    }
    const auto outputs =
        targets.emit == ProjectEmit::kHtml     ? driver::project::PageOutputs(documents.back())
        : targets.emit == ProjectEmit::kFolder ? driver::project::FolderOutputs(documents.back())
                                               : driver::project::ShaderOutputs(documents.back());
    const bool single = outputs.size() == 1;
    if (!single && targets.out_dir.empty() && !outputs.empty()) {
      std::fprintf(stderr, "shaderport port: %s gives %zu files: use --out-dir%s\n",
                   input.path.string().c_str(), outputs.size(),
                   targets.emit == ProjectEmit::kShaders ? " (or --emit html for one page)" : "");
      return kExitUsage;
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
  if (!targets.out_dir.empty()) {
    const std::string clash = driver::OutputClash(input_paths, target_paths);
    if (!clash.empty()) {
      std::fprintf(stderr, "shaderport port: error: %s; nothing was written\n", clash.c_str());
      return kExitUsage;
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
    const std::string why = driver::WriteFileAtomically(target_paths[i], texts[i]);
    if (!why.empty()) {
      std::fprintf(stderr, "shaderport port: %s\n", why.c_str());
      exit_code = kExitInternal;
    }
  }
  std::vector<driver::PortResult> findings;
  for (const auto& document : documents) findings.push_back(document.Findings());
  if (!driver::HasFindings(findings)) return exit_code;
  const bool color = ::isatty(STDERR_FILENO) != 0 && std::getenv("NO_COLOR") == nullptr;
  std::fputs(driver::FormatPortFindings(findings, sources, color).c_str(), stderr);
  return std::max(exit_code, kExitFindings);
}

}  // namespace shaderport::cli
