// The options and the message of an empty run (docs/cli.md, "Paths"): paths that
// hold no shader file are a usage error unless --allow-empty; the config's
// exclude globs apply to named files too unless --no-force-exclude.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace shaderport::cli {

// Registers --allow-empty and --no-force-exclude on `command`.
void AddEmptyInputOptions(CLI::App& command, bool& allow_empty, bool& no_force_exclude);

// "no shader files to check in 'a', 'b' (--allow-empty accepts an empty run)"
std::string NothingToDo(const std::vector<std::string>& paths, const std::string& verb);

}  // namespace shaderport::cli
