// `shaderport port`: WebGL2 (GLSL ES 3.00) from ShaderToy, WebGL1 or harness code.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "base/printable.h"
#include "cli_errors.h"
#include "commands.h"
#include "driver/check_projects.h"
#include "driver/dialect.h"
#include "driver/parallel_for.h"
#include "driver/port/emit_ported.h"
#include "driver/port/link_pairs.h"
#include "driver/port/output_files.h"
#include "driver/port/port_file.h"
#include "driver/port/port_report.h"
#include "driver/project/folder_project.h"
#include "driver/read_input.h"
#include "model/harness_dialect.h"
#include "option_names.h"
#include "port_arguments.h"
#include "port_projects.h"
#include "progress_line.h"
#include "toolchain/emit.h"

namespace shaderport::cli {
namespace {

struct PortArgs {
  InputArguments input;
  std::string output;
  std::string out_dir;
  std::string dialect;
  std::vector<std::string> channels;
  std::string stage;
  std::string emit = "essl";
  std::string optimize;
  int hlsl_shader_model = 50;
  int msl_version = 20000;
  unsigned jobs = 0;  // unsigned: CLI11 refuses "-1" as it does for check
  std::string progress = "auto";
  std::string fail_on = "error";
  bool write_invalid = false;
};

int RunPort(const PortArgs& args) {
  const std::optional<ProgressMode> progress_mode = ParseProgressMode(args.progress);
  if (!progress_mode) return UsageError(UnknownName("--progress", args.progress, kWhenNames));
  // A page is made from the ported shaders; a folder is the project as written.
  const bool emit_html = args.emit == "html";
  const bool emit_folder = args.emit == "folder";
  const auto emit_kind = emit_html || emit_folder ? std::optional(toolchain::EmitKind::kEssl)
                                                  : toolchain::EmitKindFromName(args.emit);
  if (!emit_kind) return UsageError(UnknownName("--emit", args.emit, kEmitNames));
  const std::optional<Severity> fail_on = SeverityFromName(args.fail_on);
  if (!fail_on) return UsageError(UnknownName("--fail-on", args.fail_on, kSeverityNames));
  SourceManager sources;
  driver::PortOptions options;
  options.mode = rule::PortMode::kPort;
  std::optional<model::HarnessDialect> harness;
  if (!ApplyPortArguments({args.dialect, args.channels, args.stage}, options, sources, harness)) {
    return kExitUsage;
  }
  toolchain::EmitOptions emit_options;
  emit_options.kind = *emit_kind;
  if (!args.optimize.empty()) emit_options.optimize = args.optimize;
  emit_options.hlsl_shader_model = args.hlsl_shader_model;
  emit_options.msl_version = args.msl_version;
  bool config_failed = false;
  auto inputs = SelectInputFiles(args.input, "port", config_failed);
  if (!inputs) return kExitUsage;
  driver::RelativeToCommonRoot(*inputs);
  const int config_exit = config_failed ? kExitFindings : kExitOk;
  // A page may draw two files (a vertex and a fragment shader): --emit html checks -o.
  if (!args.output.empty() && inputs->size() != 1 && !emit_html) {
    return UsageError("-o takes exactly one input file, and the paths hold " +
                      std::to_string(inputs->size()) + " (use --out-dir)");
  }
  if (inputs->empty()) return config_exit;  // --allow-empty, or all excluded
  // Standard output holds one shader: two would run together into one invalid text.
  if (args.output.empty() && args.out_dir.empty() && inputs->size() > 1 && !emit_html) {
    return UsageError("the paths hold " + std::to_string(inputs->size()) +
                      " input files and standard output takes one shader: use --out-dir DIR");
  }
  if (!args.output.empty()) {
    std::vector<std::filesystem::path> read;
    for (const driver::InputFile& input : *inputs) read.push_back(input.path);
    const std::string clash = OutputReplacesInput("-o", args.output, read);
    if (!clash.empty()) return UsageError(clash);
  }
  // ShaderToy projects (and any input of --emit html) give several files or a page.
  const bool any_project =
      std::any_of(inputs->begin(), inputs->end(), [](const driver::InputFile& input) {
        return driver::IsProjectDocument(input.path) ||
               !driver::project::ProjectFolderOf(input.path).empty();
      });
  if (emit_html || emit_folder || any_project) {
    if (*emit_kind != toolchain::EmitKind::kEssl)
      return UsageError("ShaderToy projects are ported with --emit essl, html or folder");
    const ProjectEmit emit = emit_html     ? ProjectEmit::kHtml
                             : emit_folder ? ProjectEmit::kFolder
                                           : ProjectEmit::kShaders;
    const int code = PortProjectInputs(
        *inputs, options, {args.output, args.out_dir, emit, *fail_on, args.write_invalid}, sources);
    return std::max(code, config_exit);
  }

  ProgressLine progress(*progress_mode, "porting");
  std::mutex progress_mutex;
  size_t files_done = 0;
  std::vector<driver::PortResult> results(inputs->size());
  std::vector<driver::EmittedOutput> emitted(inputs->size());
  driver::ParallelFor(inputs->size(), args.jobs, [&](size_t i) {
    results[i] = driver::PortFile((*inputs)[i].path, OptionsFor(options, (*inputs)[i]), sources);
    if (*emit_kind != toolchain::EmitKind::kEssl && results[i].HasOutput()) {
      emitted[i] = driver::EmitPorted(results[i], emit_options, sources);
    }
    const std::lock_guard lock(progress_mutex);
    progress.Update(++files_done, inputs->size());
  });
  progress.Clear();

  // Stages ported together must still link as one program.
  if (*emit_kind == toolchain::EmitKind::kEssl) driver::LinkPortedPairs(results);

  // What each input gives and where it goes, decided before anything is written.
  std::vector<std::optional<std::string>> outputs(results.size());
  std::vector<std::filesystem::path> input_paths;
  std::vector<std::filesystem::path> targets(results.size());
  std::vector<std::filesystem::path> unwritten;
  for (size_t i = 0; i < results.size(); ++i) {
    const driver::PortResult& result = results[i];
    input_paths.push_back((*inputs)[i].path);
    if (!result.HasOutput()) continue;  // its findings say why
    if (!result.validated && !args.write_invalid) {
      unwritten.push_back((*inputs)[i].path);
      continue;
    }
    std::string extension = result.output_stage == model::Stage::kVertex ? ".vert" : ".frag";
    if (*emit_kind == toolchain::EmitKind::kEssl) {
      outputs[i] = result.text;
    } else {
      if (emitted[i].output.empty()) continue;  // the leg reported why
      outputs[i] = std::move(emitted[i].output);
      if (!emitted[i].extension.empty()) extension = emitted[i].extension;
      if (emit_options.optimize) {
        std::fprintf(stderr, "%s: SPIR-V %zu -> %zu words (-%s)\n",
                     EscapeControlCharacters((*inputs)[i].path.string()).c_str(),
                     emitted[i].words_before, emitted[i].words_after,
                     emit_options.optimize->c_str());
      }
    }
    if (!args.output.empty()) targets[i] = args.output;
    if (!args.out_dir.empty()) {
      targets[i] = driver::OutDirPath(args.out_dir, (*inputs)[i].relative, extension);
    }
  }
  // -o names its one target; --out-dir makes them up, so it must not make two
  // alike or replace an input.
  const std::string clash = args.out_dir.empty() ? "" : driver::OutputClash(input_paths, targets);
  if (!clash.empty()) return UsageError(clash + "; nothing was written");

  int exit_code = driver::AllConverged(results) ? config_exit : kExitInternal;
  for (size_t i = 0; i < results.size(); ++i) {
    if (!outputs[i]) continue;
    const std::string& output = *outputs[i];
    if (!targets[i].empty()) {
      const std::filesystem::path& target = targets[i];
      std::error_code error;
      if (target.has_parent_path())
        std::filesystem::create_directories(target.parent_path(), error);
      const std::string why = file_io::WriteFileAtomically(target, output);
      if (!why.empty()) {
        PrintError(why);
        exit_code = kExitInternal;
      }
    } else {
      std::fwrite(output.data(), 1, output.size(), stdout);
    }
  }
  if (!driver::HasFindings(results)) return exit_code;
  const bool color = ::isatty(STDERR_FILENO) != 0 && std::getenv("NO_COLOR") == nullptr;
  std::fputs(driver::FormatPortFindings(results, sources, color).c_str(), stderr);
  PrintUnwritten(unwritten);
  return std::max(exit_code, driver::FailsAt(results, *fail_on) ? kExitFindings : kExitOk);
}

}  // namespace

void AddPortCommand(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<PortArgs>();
  CLI::App* command =
      app.add_subcommand("port", "Port ShaderToy / WebGL1 shaders to WebGL2 (GLSL ES 3.00)");
  AddInputOptions(*command, args->input);
  auto* output = command->add_option("-o,--output", args->output, "Write the result here");
  auto* out_dir = command->add_option("--out-dir", args->out_dir,
                                      "Write each result under DIR (same relative name)");
  output->excludes(out_dir);
  command->add_option("--dialect", args->dialect, "shadertoy|webgl1|webgl2 or a dialect TOML");
  command
      ->add_option("--channel", args->channels,
                   "Sampler type of a channel: N=2d|cube|3d (repeatable)")
      ->allow_extra_args(false);
  command->add_option("--stage", args->stage, "vertex|fragment (default: detected)");
  command->add_option(
      "--emit", args->emit,
      "essl (default), spirv, spvasm, hlsl, msl, essl-roundtrip, reflect, html (a WebGL2 "
      "page per ShaderToy project or pass)");
  command->add_option("--opt", args->optimize, "Optimise the SPIR-V: O (speed) or Os (size)");
  command->add_option("--hlsl-shader-model", args->hlsl_shader_model,
                      "HLSL shader model for --emit hlsl, e.g. 50 (default) or 60");
  command->add_option("--msl-version", args->msl_version,
                      "MSL version for --emit msl, e.g. 20000 (2.0, default)");
  command->add_option("-j,--jobs", args->jobs, "Files ported in parallel (default: all cores)");
  AddFailOnOption(*command, args->fail_on);
  command->add_flag("--write-invalid", args->write_invalid,
                    "Write (or print) a ported shader even when it does not compile");
  command
      ->add_option("--progress", args->progress,
                   "auto | always | never: a progress line on standard error (auto: on a "
                   "terminal, once a run lasts a second)")
      ->capture_default_str();
  command->callback([args, &exit_code] { exit_code = RunPort(*args); });
}

}  // namespace shaderport::cli
