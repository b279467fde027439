// What CLI11 cannot say in the contract's words (docs/cli.md, "Exit codes and
// errors"): the command word (`help`, an unknown command) and CLI11's own parse
// errors, rewritten as `shaderport: error: ...` with "did you mean" suggestions.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

namespace shaderport::cli {

// Handles what comes before CLI11 parses: no command, `help`, `help COMMAND` and a
// first word that names no command. Returns the exit code when it handled the run,
// nullopt when CLI11 should parse.
std::optional<int> HandleCommandWord(CLI::App& app, int argc, char** argv);

// One line in the contract's words for an error CLI11 threw while parsing.
std::string DescribeParseError(CLI::App& app, const CLI::ParseError& error);

}  // namespace shaderport::cli
