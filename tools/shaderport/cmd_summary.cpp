#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "base/printable.h"
#include "cli_errors.h"
#include "commands.h"
#include "driver/summary.h"
#include "empty_input.h"

namespace shaderport::cli {
namespace {

int RunSummary(const std::vector<std::string>& args, unsigned jobs) {
  std::vector<std::filesystem::path> paths(args.begin(), args.end());
  std::vector<std::string> path_errors;
  const std::vector<driver::SummaryRow> rows = driver::Summarize(paths, jobs, path_errors);
  for (const std::string& error : path_errors) PrintError(error);
  if (rows.empty() && path_errors.empty()) return UsageError(NothingToDo(args, "summarise"));
  std::printf("%-48s %-9s %-8s %7s %7s %6s %11s %9s %6s\n", "file", "dialect", "stage", "bytes",
              "tokens", "nodes", "typed", "mismatch", "errors");
  driver::SummaryRow total;
  size_t unreadable = 0;
  for (const driver::SummaryRow& row : rows) {
    if (!row.problem.empty()) {
      std::printf("%-48s %s\n", EscapeControlCharacters(row.path).c_str(),
                  EscapeControlCharacters(row.problem).c_str());
      ++unreadable;
      continue;
    }
    const std::string typed = std::to_string(row.typed) + "/" + std::to_string(row.expressions);
    std::printf("%-48s %-9s %-8s %7zu %7zu %6zu %11s %9zu %6zu\n",
                EscapeControlCharacters(row.path).c_str(), row.dialect.c_str(), row.stage.c_str(),
                row.bytes, row.tokens, row.nodes, typed.c_str(), row.mismatches, row.errors);
    total.bytes += row.bytes;
    total.tokens += row.tokens;
    total.nodes += row.nodes;
    total.expressions += row.expressions;
    total.typed += row.typed;
    total.mismatches += row.mismatches;
    total.errors += row.errors;
  }
  std::printf(
      "%zu files (%zu unreadable): %zu bytes, %zu tokens, %zu nodes, %zu of %zu "
      "expressions typed, %zu type mismatches, %zu front-end errors\n",
      rows.size(), unreadable, total.bytes, total.tokens, total.nodes, total.typed,
      total.expressions, total.mismatches, total.errors);
  if (!path_errors.empty()) return kExitUsage;
  return unreadable > 0 || total.errors > 0 ? kExitFindings : kExitOk;
}

}  // namespace

void AddSummaryCommand(CLI::App& app, int& exit_code) {
  auto paths = std::make_shared<std::vector<std::string>>();
  auto jobs = std::make_shared<unsigned>(0);
  auto* command =
      app.add_subcommand("summary", "Parse shaders and print what the front end makes of each");
  command->add_option("paths", *paths, "Files and directories")->required();
  command->add_option("-j,--jobs", *jobs, "Files parsed in parallel (default: all cores)");
  command->callback([paths, jobs, &exit_code] { exit_code = RunSummary(*paths, *jobs); });
}

}  // namespace shaderport::cli
