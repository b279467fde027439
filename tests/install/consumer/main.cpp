// Checks the files named on the command line through the installed library and
// prints the text report: the smallest useful program built on shaderport.
#include <cstdio>
#include <string>

#include "driver/check_pipeline.h"
#include "report/output_format.h"

int main(int argc, char** argv) {
  shaderport::driver::CheckOptions options;
  for (int i = 1; i < argc; ++i) options.paths.emplace_back(argv[i]);
  options.use_config = false;
  options.jobs = 1;
  shaderport::driver::CheckRun run = shaderport::driver::RunCheck(options);
  shaderport::SortReport(run.report);
  const std::string text = shaderport::FormatReport(run.report, shaderport::OutputFormat::kText,
                                                    shaderport::ReportOptions{});
  std::fwrite(text.data(), 1, text.size(), stdout);
  return run.failed ? 1 : 0;
}
