// The commands and options of the CLI as data, read from the CLI11 app that parses
// them, so that shell completion and the man page can never disagree with --help.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace shaderport::cli {

struct OptionRow {
  std::vector<std::string> long_names;   // without "--"
  std::vector<std::string> short_names;  // without "-"
  std::string description;
  std::string value_name;           // "" for a flag
  std::vector<std::string> values;  // a closed set (--format), else empty
  bool takes_path = false;          // the value is a file or directory
};

struct CommandRow {
  std::string name;
  std::string description;
  std::vector<OptionRow> options;  // --help first
  std::string positional;          // "PATH...", "RULE" or "" when it takes none
};

// Every subcommand of `app` in the order they were added, with "help".
std::vector<CommandRow> CommandTable(const CLI::App& app);

}  // namespace shaderport::cli
