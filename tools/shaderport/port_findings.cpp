#include "port_findings.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "cli_errors.h"
#include "commands.h"
#include "driver/port/port_report.h"

namespace shaderport::cli {

int PrintPortFindings(std::span<const driver::PortResult> results, const SourceManager& sources,
                      std::span<const std::filesystem::path> unwritten, int exit_code,
                      Severity fail_on) {
  if (!driver::HasFindings(results)) return exit_code;
  const bool color = ::isatty(STDERR_FILENO) != 0 && std::getenv("NO_COLOR") == nullptr;
  std::fputs(driver::FormatPortFindings(results, sources, color).c_str(), stderr);
  PrintUnwritten(unwritten);
  return std::max(exit_code, driver::FailsAt(results, fail_on) ? kExitFindings : kExitOk);
}

}  // namespace shaderport::cli
