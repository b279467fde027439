// `shaderport dump`: the front end's structures as text, for people and goldens.
#pragma once

#include <filesystem>
#include <string>

#include "report/check_report.h"
#include "source/source_manager.h"

namespace shaderport::driver {

enum class DumpKind { kTokens, kPpTokens, kAst, kTypes };

struct DumpResult {
  std::string text;        // the dump itself
  FileReport diagnostics;  // front-end errors (or the input error) of the file
};

// Reads `path` (with the input limits), runs the front end for its detected
// dialect and dumps the requested structure.
DumpResult DumpFile(const std::filesystem::path& path, DumpKind kind, SourceManager& sources);

}  // namespace shaderport::driver
