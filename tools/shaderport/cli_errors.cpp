#include "cli_errors.h"

#include <cstdio>

#include "base/did_you_mean.h"
#include "commands.h"

namespace shaderport::cli {

void PrintError(std::string_view message) {
  std::fprintf(stderr, "shaderport: error: %.*s\n", static_cast<int>(message.size()),
               message.data());
}

int UsageError(std::string_view message) {
  PrintError(message);
  return kExitUsage;
}

std::string DidYouMean(std::string_view typed, std::span<const std::string> names) {
  const std::optional<std::string> near = ClosestName(typed, names);
  return near ? "; did you mean '" + *near + "'?" : "";
}

std::string UnknownName(std::string_view what, std::string_view typed,
                        std::span<const std::string> names) {
  std::string message = "unknown " + std::string(what) + " '" + std::string(typed) + "'";
  const std::string suggestion = DidYouMean(typed, names);
  if (!suggestion.empty() || names.empty()) return message + suggestion;
  message += " (expected ";
  for (size_t i = 0; i < names.size(); ++i) {
    if (i > 0) message += i + 1 == names.size() ? " or " : ", ";
    message += names[i];
  }
  return message + ")";
}

}  // namespace shaderport::cli
