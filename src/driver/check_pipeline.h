// `shaderport check`: every file through input checks, our front end, glslang
// as the browser or shadertoy.com would compile it, suppressions and the
// project's rule configuration.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "driver/check_options.h"
#include "report/check_report.h"
#include "source/source_manager.h"

namespace shaderport::driver {

struct CheckRun {
  std::unique_ptr<SourceManager> sources = std::make_unique<SourceManager>();
  CheckReport report;                     // in input order; report.sources points at `sources`
  std::vector<std::string> usage_errors;  // missing paths, bad config files given with --config
  bool failed = false;                    // some finding at or above the fail-on level
  bool internal_error = false;            // some internal/* diagnostic: a shaderport bug
};

CheckRun RunCheck(const CheckOptions& options);

}  // namespace shaderport::driver
