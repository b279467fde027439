// What remains after `fix` or `port`, in the text report format.
#pragma once

#include <span>
#include <string>

#include "driver/port/port_file.h"

namespace shaderport::driver {

// True when any warning or error remains in `results`.
bool HasFindings(std::span<const PortResult> results);

// True when a finding at or above `fail_on` remains (`fix`/`port --fail-on`).
bool FailsAt(std::span<const PortResult> results, Severity fail_on);

// False when the fixes of one of `results` did not settle (see PortResult::converged):
// nothing of it was written, and the run exits 3.
bool AllConverged(std::span<const PortResult> results);

// The remaining findings of every result, as `check` prints them.
std::string FormatPortFindings(std::span<const PortResult> results, const SourceManager& sources,
                               bool color);

}  // namespace shaderport::driver
