// What `fix` and `port` print last: the remaining findings on standard error, as
// `check` prints them, and the exit code they make.
#pragma once

#include <filesystem>
#include <span>

#include "diag/diagnostic.h"
#include "driver/port/port_file.h"
#include "source/source_manager.h"

namespace shaderport::cli {

// Prints the findings of `results` and a note for each `unwritten` input, and returns
// `exit_code` raised to 1 when a finding is at or above `fail_on`. Prints nothing
// (the notes neither) when no warning or error remains.
int PrintPortFindings(std::span<const driver::PortResult> results, const SourceManager& sources,
                      std::span<const std::filesystem::path> unwritten, int exit_code,
                      Severity fail_on);

}  // namespace shaderport::cli
