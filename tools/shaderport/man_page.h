// The manual page, shaderport(1), in roff, written from the command table
// (`shaderport man`; the build installs it as share/man/man1/shaderport.1).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "command_table.h"

namespace shaderport::cli {

std::string ManPage(const std::vector<CommandRow>& commands, std::string_view version);

}  // namespace shaderport::cli
