// Mesa's compiler log lines: `0:5(2): error: message`. The first number is the
// source string, then the line; the "column" counts each whitespace run as one
// character (toolchain-facts §4), so only the line is used.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace shaderport::render {

struct MesaLogEntry {
  uint32_t line = 0;  // 0: no location
  bool is_error = true;
  std::string message;
};

std::vector<MesaLogEntry> ParseMesaLog(std::string_view log);

}  // namespace shaderport::render
