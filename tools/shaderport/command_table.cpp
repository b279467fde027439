#include "command_table.h"

#include <algorithm>
#include <map>
#include <span>

#include "option_names.h"

namespace shaderport::cli {
namespace {

std::vector<std::string> ToVector(std::span<const std::string> names) {
  return {names.begin(), names.end()};
}

// The closed value sets, by option and (where two commands differ) command.
std::vector<std::string> ClosedValues(const std::string& command, const std::string& option) {
  if (option == "format") {
    return command == "merge" ? ToVector(kMergeFormatNames) : ToVector(kFormatNames);
  }
  static const std::map<std::string, std::span<const std::string>> kSets = {
      {"dialect", kDialectNames},  {"target", kTargetNames},  {"stage", kStageNames},
      {"fail-on", kSeverityNames}, {"color", kWhenNames},     {"progress", kWhenNames},
      {"emit", kEmitNames},        {"backend", kBackendNames}};
  const auto found = kSets.find(option);
  return found == kSets.end() ? std::vector<std::string>{} : ToVector(found->second);
}

bool TakesPath(const std::string& option) {
  static const std::vector<std::string> kPathOptions = {
      "output",         "out-dir",        "config",    "baseline", "common",  "html",
      "write-baseline", "stdin-filename", "cache-dir", "sarif",    "save-png"};
  return std::find(kPathOptions.begin(), kPathOptions.end(), option) != kPathOptions.end();
}

OptionRow RowOf(const std::string& command, const CLI::Option& option) {
  OptionRow row;
  row.long_names = option.get_lnames();
  row.short_names = option.get_snames();
  row.description = option.get_description();
  if (option.get_type_size() != 0) {
    row.value_name = option.get_type_name();
    const std::string first = row.long_names.empty() ? "" : row.long_names.front();
    row.values = ClosedValues(command, first);
    row.takes_path = TakesPath(first);
    if (row.value_name.empty()) row.value_name = "VALUE";
  }
  return row;
}

}  // namespace

std::vector<CommandRow> CommandTable(const CLI::App& app) {
  std::vector<CommandRow> table;
  for (const CLI::App* command : app.get_subcommands([](const CLI::App*) { return true; })) {
    CommandRow row;
    row.name = command->get_name();
    row.description = command->get_description();
    for (const CLI::Option* option : command->get_options()) {
      if (option->get_positional()) {
        std::string name = option->get_name(true);
        std::transform(name.begin(), name.end(), name.begin(), ::toupper);
        row.positional = option->get_items_expected_max() > 1 ? name + "..." : name;
        continue;
      }
      row.options.push_back(RowOf(row.name, *option));
    }
    table.push_back(std::move(row));
  }
  table.push_back({"help", "Show the help of shaderport or of one command", {}, "COMMAND"});
  return table;
}

}  // namespace shaderport::cli
