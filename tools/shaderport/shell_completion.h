// Shell completion scripts for bash, zsh and fish, written from the command table
// (`shaderport completion SHELL`): commands, their options, the closed value sets
// (--format, --target...) and file names where a command takes paths.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "command_table.h"

namespace shaderport::cli {

inline const std::vector<std::string> kShellNames = {"bash", "zsh", "fish"};

// The script for `shell` (one of kShellNames); nothing for another name.
std::optional<std::string> CompletionScript(std::string_view shell,
                                            const std::vector<CommandRow>& commands);

}  // namespace shaderport::cli
