#include "parse_errors.h"

#include <algorithm>
#include <cstdio>
#include <regex>
#include <string_view>
#include <vector>

#include "cli_errors.h"
#include "commands.h"

namespace shaderport::cli {
namespace {

std::vector<CLI::App*> Commands(CLI::App& app) {
  return app.get_subcommands([](CLI::App*) { return true; });
}

std::vector<std::string> CommandNames(CLI::App& app) {
  std::vector<std::string> names;
  for (CLI::App* command : Commands(app)) names.push_back(command->get_name());
  names.emplace_back("help");
  return names;
}

CLI::App* FindCommand(CLI::App& app, std::string_view name) {
  for (CLI::App* command : Commands(app)) {
    if (command->get_name() == name) return command;
  }
  return nullptr;
}

int UnknownCommand(CLI::App& app, std::string_view word) {
  return UsageError("unknown command '" + std::string(word) + "'" +
                    DidYouMean(word, CommandNames(app)) +
                    " (run 'shaderport help' for the list of commands)");
}

// Every spelling of the command's options: --long and -s.
std::vector<std::string> OptionNames(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::Option* option : command.get_options()) {
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
    for (const std::string& name : option->get_snames()) names.push_back("-" + name);
  }
  return names;
}

// The command CLI11 was parsing: the last one selected, else the app itself.
CLI::App& CurrentCommand(CLI::App& app) {
  CLI::App* current = &app;
  while (!current->get_subcommands().empty()) current = current->get_subcommands().back();
  return *current;
}

std::string Where(const CLI::App& app, const CLI::App& command) {
  return &command == &app ? "" : " for '" + command.get_name() + "'";
}

std::string DescribeExtras(CLI::App& app) {
  CLI::App& command = CurrentCommand(app);
  const std::vector<std::string> extras = command.remaining();
  if (extras.empty()) return "unexpected arguments";
  const std::string& first = extras.front();
  if (first.size() > 1 && first[0] == '-') {
    const std::string name = first.substr(0, first.find('='));
    return "unknown option '" + name + "'" + Where(app, command) +
           DidYouMean(name, OptionNames(command));
  }
  return "unexpected argument '" + first + "'" + Where(app, command);
}

std::string Lowercased(std::string text) {
  if (!text.empty() && text[0] >= 'A' && text[0] <= 'Z') text[0] = static_cast<char>(text[0] + 32);
  return text;
}

}  // namespace

std::optional<int> HandleCommandWord(CLI::App& app, int argc, char** argv) {
  if (argc < 2)
    return UsageError("no command given (run 'shaderport help' for the list of commands)");
  const std::string_view word = argv[1];
  if (word.starts_with("-")) {
    // Before a command only --help, -h and --version mean anything.
    const std::vector<std::string> options = {"--help", "-h", "--version"};
    const std::string name(word.substr(0, word.find('=')));
    if (std::find(options.begin(), options.end(), name) != options.end()) return std::nullopt;
    return UsageError("unknown option '" + name + "'" + DidYouMean(name, options) +
                      " (options go after the command: 'shaderport help COMMAND')");
  }
  if (word == "help") {
    // `help help` is the general help, as git's is.
    if (argc == 2 || (argc == 3 && std::string_view(argv[2]) == "help")) {
      std::fputs(app.help().c_str(), stdout);
      return kExitOk;
    }
    CLI::App* command = FindCommand(app, argv[2]);
    if (command == nullptr) return UnknownCommand(app, argv[2]);
    if (argc > 3) return UsageError("help takes one command");
    std::fputs(command->help(app.get_name()).c_str(), stdout);
    return kExitOk;
  }
  if (FindCommand(app, word) == nullptr) return UnknownCommand(app, word);
  return std::nullopt;
}

std::string DescribeParseError(CLI::App& app, const CLI::ParseError& error) {
  if (dynamic_cast<const CLI::ExtrasError*>(&error) != nullptr) return DescribeExtras(app);
  const CLI::App& command = CurrentCommand(app);
  const std::string prefix = &command == &app ? "" : command.get_name() + ": ";
  const std::string message = error.what();
  std::smatch match;
  static const std::regex kMissingValue(R"(^(\S+): \d+ required \S+ missing$)");
  if (std::regex_match(message, match, kMissingValue)) {
    return prefix + "option '" + match[1].str() + "' needs a value";
  }
  static const std::regex kConversion(R"(^Could not convert: (\S+) = (.*)$)");
  if (std::regex_match(message, match, kConversion)) {
    return prefix + "invalid value '" + match[2].str() + "' for " + match[1].str();
  }
  static const std::regex kExcludes(R"(^(\S+) excludes (\S+)$)");
  if (std::regex_match(message, match, kExcludes)) {
    return prefix + match[1].str() + " and " + match[2].str() + " cannot be used together";
  }
  return prefix + Lowercased(message);
}

}  // namespace shaderport::cli
