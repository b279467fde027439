// Reads one input file within the size limit and rejects what is not shader text.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "diag/diagnostic.h"

namespace shaderport::driver {

struct InputText {
  std::optional<std::string> text;  // empty optional when the file was rejected
  std::string rule_id;              // why it was rejected ("input/too-large", ...)
  std::string message;
};

// The size is checked before anything is read, so a huge file costs nothing.
InputText ReadInputFile(const std::filesystem::path& path);

// Classifies text already in memory (stdin, tests): "" when it looks like shader source.
InputText ClassifyInputText(std::string text);

}  // namespace shaderport::driver
