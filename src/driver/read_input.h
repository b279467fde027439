// Reads one input file within the size limit and rejects what is not shader text.
#pragma once

#include <filesystem>
#include <istream>
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

// Reads a stream (standard input) within the same limit: reading stops one buffer
// (64 KiB) past the limit, so an endless stream costs nothing.
InputText ReadInputStream(std::istream& in);

// Classifies text already in memory (stdin, tests): "" when it looks like shader source.
InputText ClassifyInputText(std::string text);

}  // namespace shaderport::driver
