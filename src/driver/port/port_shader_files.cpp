#include "driver/port/port_shader_files.h"

#include <mutex>
#include <optional>
#include <string>

#include "driver/parallel_for.h"
#include "driver/port/emit_ported.h"
#include "driver/port/link_pairs.h"
#include "driver/port/output_files.h"
#include "driver/port/port_report.h"

namespace shaderport::driver {

namespace fs = std::filesystem;

void PortShaderFiles(const std::vector<InputFile>& inputs, const PortRunOptions& options,
                     SourceManager& sources, PortRun& run) {
  const bool essl = options.emit.kind == toolchain::EmitKind::kEssl;
  std::mutex progress_mutex;
  size_t files_done = 0;
  std::vector<PortResult>& results = run.results;
  results.resize(inputs.size());
  std::vector<EmittedOutput> emitted(inputs.size());
  ParallelFor(inputs.size(), options.jobs, [&](size_t i) {
    results[i] = PortFile(inputs[i].path, OptionsFor(options.port, inputs[i]), sources);
    if (!essl && results[i].HasOutput()) {
      emitted[i] = EmitPorted(results[i], options.emit, sources);
    }
    if (!options.progress) return;
    const std::lock_guard lock(progress_mutex);
    options.progress(++files_done, inputs.size());
  });

  // Stages ported together must still link as one program.
  if (essl) LinkPortedPairs(results);

  // What each input gives and where it goes, decided before anything is written.
  std::vector<std::optional<std::string>> outputs(results.size());
  std::vector<fs::path> input_paths;
  std::vector<fs::path> targets(results.size());
  for (size_t i = 0; i < results.size(); ++i) {
    const PortResult& result = results[i];
    input_paths.push_back(inputs[i].path);
    if (!result.HasOutput()) continue;  // its findings say why
    if (!result.validated && !options.write_invalid) {
      run.unwritten.push_back(inputs[i].path);
      continue;
    }
    std::string extension = result.output_stage == model::Stage::kVertex ? ".vert" : ".frag";
    if (essl) {
      outputs[i] = result.text;
    } else {
      if (emitted[i].output.empty()) continue;  // the leg reported why
      outputs[i] = std::move(emitted[i].output);
      if (!emitted[i].extension.empty()) extension = emitted[i].extension;
      if (options.emit.optimize) {
        run.optimised.push_back({inputs[i].path, emitted[i].words_before, emitted[i].words_after});
      }
    }
    if (!options.output.empty()) targets[i] = options.output;
    if (!options.out_dir.empty())
      targets[i] = OutDirPath(options.out_dir, inputs[i].relative, extension);
  }
  // -o names its one target; --out-dir makes them up, so it must not make two
  // alike or replace an input.
  if (!options.out_dir.empty()) {
    const std::string clash = OutputClash(input_paths, targets);
    if (!clash.empty()) {
      run.usage_error = clash + "; nothing was written";
      return;
    }
  }
  run.unsettled = !AllConverged(results);
  for (size_t i = 0; i < results.size(); ++i) {
    if (!outputs[i]) continue;
    if (targets[i].empty()) {
      run.standard_output += *outputs[i];
    } else if (std::string why = WriteOutput(targets[i], *outputs[i]); !why.empty()) {
      run.write_errors.push_back(std::move(why));
    }
  }
}

}  // namespace shaderport::driver
