#include "driver/input_selection.h"

#include <algorithm>

namespace shaderport::driver {

namespace fs = std::filesystem;

bool InputSelection::ConfigFailed() const {
  return std::any_of(config_problems.begin(), config_problems.end(),
                     [](const FileReport& file) { return HasErrors(file.diagnostics); });
}

InputSelection SelectInputs(const InputSelectionOptions& options, ConfigLookup& configs) {
  InputSelection selection;
  if (!configs.ExplicitConfigError().empty()) {
    selection.errors.push_back(configs.ExplicitConfigError());
    return selection;
  }
  InputSet walked;
  if (options.stdin_name) {
    // Excluded, the text is not checked or fixed (ruff).
    if (options.force_exclude && !configs.Includes(*options.stdin_name)) {
      walked.dropped = 1;
    } else {
      walked.files.push_back({*options.stdin_name, *options.stdin_name, true});
    }
  } else {
    walked = WalkInputs(
        options.paths, [&](const fs::path& file) { return configs.Includes(file); },
        options.force_exclude);
  }
  selection.files = std::move(walked.files);
  selection.errors = std::move(walked.errors);
  selection.unmatched = std::move(walked.unmatched);
  selection.dropped = walked.dropped;
  selection.config_problems = configs.TakeProblems();
  return selection;
}

ConfiguredInputs SelectConfiguredInputs(const InputSelectionOptions& options) {
  ConfiguredInputs inputs;
  ConfigLookup configs(options.use_config, options.config, *inputs.config_sources);
  inputs.selection = SelectInputs(options, configs);
  for (InputFile& input : inputs.selection.files) {
    if (const Config* config = configs.For(input.path)) {
      const FileSettings settings = SettingsFor(*config, fs::absolute(input.path));
      input.dialect = settings.dialect;
      input.stage = settings.stage;
    }
  }
  return inputs;
}

}  // namespace shaderport::driver
