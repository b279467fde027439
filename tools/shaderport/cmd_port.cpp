// `shaderport port`: WebGL2 (GLSL ES 3.00) from ShaderToy, WebGL1 or harness code.
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/printable.h"
#include "cli_errors.h"
#include "commands.h"
#include "driver/port/port_run.h"
#include "model/harness_dialect.h"
#include "option_names.h"
#include "port_arguments.h"
#include "port_findings.h"
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
  driver::PortRunOptions options;
  // A page is made from the ported shaders; a folder is the project as written.
  options.layout = args.emit == "html"     ? driver::PortLayout::kPage
                   : args.emit == "folder" ? driver::PortLayout::kFolder
                                           : driver::PortLayout::kShaders;
  const auto emit_kind = options.layout != driver::PortLayout::kShaders
                             ? std::optional(toolchain::EmitKind::kEssl)
                             : toolchain::EmitKindFromName(args.emit);
  if (!emit_kind) return UsageError(UnknownName("--emit", args.emit, kEmitNames));
  const std::optional<Severity> fail_on = SeverityFromName(args.fail_on);
  if (!fail_on) return UsageError(UnknownName("--fail-on", args.fail_on, kSeverityNames));
  SourceManager sources;
  std::optional<model::HarnessDialect> harness;
  if (!ApplyPortArguments({args.dialect, args.channels, args.stage}, options.port, sources,
                          harness)) {
    return kExitUsage;
  }
  options.emit.kind = *emit_kind;
  if (!args.optimize.empty()) options.emit.optimize = args.optimize;
  options.emit.hlsl_shader_model = args.hlsl_shader_model;
  options.emit.msl_version = args.msl_version;
  options.output = args.output;
  options.out_dir = args.out_dir;
  options.write_invalid = args.write_invalid;
  options.jobs = args.jobs;
  bool config_failed = false;
  auto inputs = SelectInputFiles(args.input, "port", config_failed);
  if (!inputs) return kExitUsage;

  ProgressLine progress(*progress_mode, "porting");
  options.progress = [&progress](size_t done, size_t total) { progress.Update(done, total); };
  const driver::PortRun run = driver::RunPort(std::move(*inputs), options, sources);
  progress.Clear();
  for (const driver::OptimisedSize& size : run.optimised) {
    std::fprintf(stderr, "%s: SPIR-V %zu -> %zu words (-%s)\n",
                 EscapeControlCharacters(size.input.string()).c_str(), size.words_before,
                 size.words_after, args.optimize.c_str());
  }
  if (!run.usage_error.empty()) return UsageError(run.usage_error);
  std::fwrite(run.standard_output.data(), 1, run.standard_output.size(), stdout);
  for (const std::string& error : run.write_errors) PrintError(error);
  const bool internal = run.unsettled || !run.write_errors.empty();
  return PrintPortFindings(run.results, sources, run.unwritten,
                           internal ? kExitInternal : (config_failed ? kExitFindings : kExitOk),
                           *fail_on);
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
