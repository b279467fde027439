// `shaderport port`: WebGL2 (GLSL ES 3.00) from ShaderToy, WebGL1 or harness code.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "driver/dialect.h"
#include "driver/parallel_for.h"
#include "driver/port/emit_ported.h"
#include "driver/port/link_pairs.h"
#include "driver/port/output_files.h"
#include "driver/port/port_file.h"
#include "driver/port/port_report.h"
#include "driver/read_input.h"
#include "port_arguments.h"
#include "rule/harness_dialect.h"
#include "toolchain/emit.h"

namespace shaderport::cli {
namespace {

struct PortArgs {
  std::vector<std::string> paths;
  std::string output;
  std::string out_dir;
  std::string dialect;
  std::vector<std::string> channels;
  std::string stage;
  std::string emit = "essl";
  std::string optimize;
  int hlsl_shader_model = 50;
  int msl_version = 20000;
  int jobs = 0;
};

std::filesystem::path OutputPathFor(const std::string& input, const std::string& out_dir,
                                    driver::Stage stage, const std::string& extension) {
  std::filesystem::path relative = std::filesystem::path(input).lexically_normal();
  if (relative.is_absolute()) relative = relative.filename();
  while (!relative.empty() && *relative.begin() == "..") {
    relative = relative.lexically_relative(*relative.begin());
  }
  relative.replace_extension(!extension.empty()                ? extension
                             : stage == driver::Stage::kVertex ? ".vert"
                                                               : ".frag");
  return std::filesystem::path(out_dir) / relative;
}

int RunPort(const PortArgs& args) {
  if (!args.output.empty() && args.paths.size() != 1) {
    std::fprintf(stderr, "shaderport port: -o takes exactly one input file (use --out-dir)\n");
    return kExitUsage;
  }
  const auto emit_kind = toolchain::EmitKindFromName(args.emit);
  if (!emit_kind) {
    std::fprintf(stderr, "shaderport port: unknown --emit kind '%s'\n", args.emit.c_str());
    return kExitUsage;
  }
  SourceManager sources;
  driver::PortOptions options;
  options.mode = rule::PortMode::kPort;
  std::optional<rule::HarnessDialect> harness;
  if (!ApplyPortArguments("port", {args.dialect, args.channels, args.stage}, options, sources,
                          harness)) {
    return kExitUsage;
  }
  toolchain::EmitOptions emit_options;
  emit_options.kind = *emit_kind;
  if (!args.optimize.empty()) emit_options.optimize = args.optimize;
  emit_options.hlsl_shader_model = args.hlsl_shader_model;
  emit_options.msl_version = args.msl_version;
  std::vector<driver::PortResult> results(args.paths.size());
  std::vector<driver::EmittedOutput> emitted(args.paths.size());
  driver::ParallelFor(args.paths.size(), static_cast<unsigned>(std::max(0, args.jobs)),
                      [&](size_t i) {
                        results[i] = driver::PortFile(args.paths[i], options, sources);
                        if (*emit_kind == toolchain::EmitKind::kEssl || results[i].read_failed) {
                          return;
                        }
                        emitted[i] = driver::EmitPorted(results[i], emit_options, sources);
                      });

  // Stages ported together must still link as one program.
  if (*emit_kind == toolchain::EmitKind::kEssl) driver::LinkPortedPairs(results);

  int exit_code = kExitOk;
  for (size_t i = 0; i < results.size(); ++i) {
    driver::PortResult& result = results[i];
    if (result.read_failed) continue;
    std::string output = result.text;
    std::string extension;
    if (*emit_kind != toolchain::EmitKind::kEssl) {
      if (emitted[i].output.empty()) continue;  // the leg reported why
      output = std::move(emitted[i].output);
      extension = emitted[i].extension;
      if (emit_options.optimize) {
        std::fprintf(stderr, "%s: SPIR-V %zu -> %zu words (-%s)\n", args.paths[i].c_str(),
                     emitted[i].words_before, emitted[i].words_after,
                     emit_options.optimize->c_str());
      }
    }
    if (!args.out_dir.empty() || !args.output.empty()) {
      const std::filesystem::path target =
          !args.output.empty()
              ? std::filesystem::path(args.output)
              : OutputPathFor(args.paths[i], args.out_dir, result.output_stage, extension);
      std::error_code error;
      if (target.has_parent_path())
        std::filesystem::create_directories(target.parent_path(), error);
      const std::string why = driver::WriteFileAtomically(target, output);
      if (!why.empty()) {
        std::fprintf(stderr, "shaderport port: %s\n", why.c_str());
        exit_code = kExitInternal;
      }
    } else {
      std::fwrite(output.data(), 1, output.size(), stdout);
    }
  }
  if (!driver::HasFindings(results)) return exit_code;
  const bool color = ::isatty(STDERR_FILENO) != 0 && std::getenv("NO_COLOR") == nullptr;
  std::fputs(driver::FormatPortFindings(results, sources, color).c_str(), stderr);
  return std::max(exit_code, kExitFindings);
}

}  // namespace

void AddPortCommand(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<PortArgs>();
  CLI::App* command =
      app.add_subcommand("port", "Port ShaderToy / WebGL1 shaders to WebGL2 (GLSL ES 3.00)");
  command->add_option("paths", args->paths, "Shader files")->required();
  auto* output = command->add_option("-o,--output", args->output, "Write the result here");
  auto* out_dir = command->add_option("--out-dir", args->out_dir,
                                      "Write each result under DIR (same relative name)");
  output->excludes(out_dir);
  command->add_option("--dialect", args->dialect, "shadertoy|webgl1|webgl2 or a dialect TOML");
  command->add_option("--channel", args->channels, "Sampler type of a channel: N=2d|cube|3d");
  command->add_option("--stage", args->stage, "vertex|fragment (default: detected)");
  command->add_option("--emit", args->emit,
                      "essl (default), spirv, spvasm, hlsl, msl, essl-roundtrip, reflect");
  command->add_option("--opt", args->optimize, "Optimise the SPIR-V: O (speed) or Os (size)");
  command->add_option("--hlsl-shader-model", args->hlsl_shader_model,
                      "HLSL shader model for --emit hlsl, e.g. 50 (default) or 60");
  command->add_option("--msl-version", args->msl_version,
                      "MSL version for --emit msl, e.g. 20000 (2.0, default)");
  command->add_option("-j,--jobs", args->jobs, "Files ported in parallel (default: all cores)");
  command->callback([args, &exit_code] { exit_code = RunPort(*args); });
}

}  // namespace shaderport::cli
