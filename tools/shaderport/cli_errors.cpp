#include "cli_errors.h"

#include <cstdio>

#include "base/did_you_mean.h"
#include "base/printable.h"
#include "commands.h"

namespace shaderport::cli {

void PrintError(std::string_view message) {
  // Messages name files, whose names may hold control characters: one line, no escapes
  // reaching the terminal.
  const std::string printable = EscapeControlCharacters(message);
  std::fprintf(stderr, "shaderport: error: %.*s\n", static_cast<int>(printable.size()),
               printable.data());
}

void PrintUnwritten(std::span<const std::filesystem::path> unwritten) {
  for (const std::filesystem::path& path : unwritten) {
    const std::string printable = EscapeControlCharacters(path.string());
    std::fprintf(stderr,
                 "shaderport: note: %s: not written: the ported shader does not compile "
                 "(--write-invalid writes it anyway)\n",
                 printable.c_str());
  }
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
