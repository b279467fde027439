// The options `fix` and `port` share: --dialect, --channel and --stage.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "driver/port/port_file.h"
#include "rule/harness_dialect.h"
#include "source/source_manager.h"

namespace shaderport::cli {

struct PortArguments {
  std::string dialect;                // shadertoy | webgl1 | webgl2 | a dialect name | FILE.toml
  std::vector<std::string> channels;  // N=2d|cube|3d
  std::string stage;                  // vertex | fragment
};

// Fills `options`; a loaded dialect lives in `harness`. Prints why and returns
// false on a bad value (a usage error).
bool ApplyPortArguments(const char* command, const PortArguments& arguments,
                        driver::PortOptions& options, SourceManager& sources,
                        std::optional<rule::HarnessDialect>& harness);

}  // namespace shaderport::cli
