// `shaderport check`: every file through input checks, our front end, glslang
// as the browser or shadertoy.com would compile it, suppressions and the
// project's rule configuration.
#pragma once

#include <cstddef>
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
  // The paths held no shader file at all, not even one the config excludes (an
  // empty directory): the caller decides whether an empty run is an error.
  bool found_nothing = false;
  size_t excluded = 0;                 // files left out by the include/exclude globs
  std::vector<std::string> unmatched;  // patterns the shell left unexpanded (InputSet)
};

CheckRun RunCheck(const CheckOptions& options);

}  // namespace shaderport::driver
