// `shaderport report --html OUT.html PATH...`: checks, ports and renders every shader
// and writes one self-contained HTML page. Findings never fail it: the page shows them.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "base/printable.h"
#include "cli_errors.h"
#include "commands.h"
#include "driver/html_report/build_report.h"
#include "driver/port/output_files.h"
#include "empty_input.h"
#include "option_names.h"

namespace shaderport::cli {
namespace {

struct ReportArgs {
  std::vector<std::string> paths;
  std::string html;
  int jobs = 0;
  unsigned size = 128;
  std::string backend;
  double timeout_seconds = 10.0;
  bool hermetic = false;
};

int RunReport(const ReportArgs& args) {
  if (args.html.empty()) return UsageError("--html OUT.html is required");
  if (args.jobs < 0) return UsageError("-j must be 0 or more");
  if (args.size < 1 || args.size > 1024) return UsageError("--size must be 1..1024");
  // NaN fails every comparison: without isfinite it would pass this test.
  if (!std::isfinite(args.timeout_seconds) || args.timeout_seconds <= 0 ||
      args.timeout_seconds > 3600) {
    return UsageError("--timeout must be more than 0 and at most 3600 seconds");
  }
  driver::HtmlReportOptions options;
  for (const std::string& path : args.paths) options.paths.emplace_back(path);
  if (const std::string clash = driver::OutputReplacesInput("--html", args.html, options.paths);
      !clash.empty()) {
    return UsageError(clash);
  }
  options.jobs = static_cast<unsigned>(args.jobs);
  options.size = args.size;
  options.tool_version = SHADERPORT_VERSION;
  if (!args.backend.empty()) {
    const auto backend = render::BackendFromName(args.backend);
    if (!backend) return UsageError(UnknownName("--backend", args.backend, kBackendNames));
    options.render.backend = *backend;
  }
  options.render.timeout =
      std::chrono::milliseconds(static_cast<int64_t>(args.timeout_seconds * 1000));
  options.render.hermetic = args.hermetic;

  const driver::HtmlReportRun run = driver::BuildHtmlReport(options);
  if (run.found_nothing && run.usage_errors.empty()) {
    return UsageError(NothingToDo(args.paths, "report on"));
  }
  for (const std::string& error : run.usage_errors) PrintError(error);
  if (!run.usage_errors.empty() && run.report.entries.empty()) return kExitUsage;
  // A file found in a directory argument is an input too.
  std::vector<std::filesystem::path> read;
  for (const driver::ReportEntry& entry : run.report.entries) read.emplace_back(entry.path);
  if (const std::string clash = driver::OutputReplacesInput("--html", args.html, read);
      !clash.empty()) {
    return UsageError(clash);
  }
  const std::string html = driver::FormatHtmlReport(run.report);
  const std::string error = file_io::WriteFileAtomically(args.html, html);
  if (!error.empty()) {
    PrintError(error);
    return kExitInternal;
  }
  const driver::ReportCounts counts = driver::CountReport(run.report);
  std::printf(
      "%s: %zu shaders; check %zu pass, %zu warn, %zu fail; port %zu pass, %zu warn, %zu fail; "
      "render %zu pass, %zu warn, %zu fail, %zu skipped; %zu thumbnails\n",
      EscapeControlCharacters(args.html).c_str(), counts.shaders, counts.check.pass,
      counts.check.warn, counts.check.fail, counts.port.pass, counts.port.warn, counts.port.fail,
      counts.render.pass, counts.render.warn, counts.render.fail, counts.render.skipped,
      counts.thumbnails);
  return run.usage_errors.empty() ? kExitOk : kExitUsage;
}

}  // namespace

void AddReportCommand(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ReportArgs>();
  auto* command = app.add_subcommand(
      "report", "Check, port and render every shader into one self-contained HTML report");
  command->add_option("paths", args->paths, "Files and directories")->required();
  command->add_option("--html", args->html, "The HTML file to write")->required();
  command->add_option("-j,--jobs", args->jobs, "Files processed in parallel (default: all cores)");
  command->add_option("--size", args->size, "Thumbnail render size in pixels (default 128)");
  command->add_option("--backend", args->backend, "osmesa or egl (default osmesa)");
  command->add_option("--timeout", args->timeout_seconds,
                      "Seconds before a render is killed (default 10)");
  command->add_flag("--hermetic", args->hermetic, "Do not use or fill Mesa's shader cache");
  command->callback([args, &exit_code] { exit_code = RunReport(*args); });
}

}  // namespace shaderport::cli
