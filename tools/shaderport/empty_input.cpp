#include "empty_input.h"

namespace shaderport::cli {

void AddEmptyInputOptions(CLI::App& command, bool& allow_empty, bool& no_force_exclude) {
  command.add_flag("--allow-empty", allow_empty,
                   "Accept paths that hold no shader file (and globs that matched nothing): "
                   "exit 0 instead of 2");
  command.add_flag("--no-force-exclude", no_force_exclude,
                   "Apply .shaderport.toml include/exclude only to files found in directories, "
                   "not to files named on the command line");
}

std::string NothingToDo(const std::vector<std::string>& paths, const std::string& verb) {
  std::string names;
  for (const std::string& path : paths) names += (names.empty() ? "'" : ", '") + path + "'";
  return "no shader files to " + verb + " in " + names + " (--allow-empty accepts an empty run)";
}

}  // namespace shaderport::cli
