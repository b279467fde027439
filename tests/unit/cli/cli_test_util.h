// Runs the real shaderport binary and captures what it prints.
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "golden.h"

namespace shaderport::testing {

struct CommandResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// Runs `command_line` in the shell: its standard output and exit code (128 + the
// signal for a killed process).
inline CommandResult RunShellLine(const std::string& command_line) {
  CommandResult result;
  FILE* pipe = ::popen(command_line.c_str(), "r");
  if (pipe == nullptr) return result;
  char buffer[65536];
  size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) result.out.append(buffer, n);
  const int status = ::pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return result;
}

// `args` is passed to the shell as is; `directory` is the working directory.
inline CommandResult RunShaderport(const std::string& args, const std::filesystem::path& directory,
                                   const std::string& environment = "NO_COLOR=1") {
  static int counter = 0;
  const std::filesystem::path err_file =
      std::filesystem::temp_directory_path() /
      ("shaderport-cli-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + ".err");
  const std::string command = "cd '" + directory.string() + "' && env " + environment + " '" +
                              SHADERPORT_BINARY + "' " + args + " 2>'" + err_file.string() + "'";
  CommandResult result = RunShellLine(command);
  result.err = ReadWholeFile(err_file);
  std::filesystem::remove(err_file);
  return result;
}

inline std::filesystem::path SourceDir() { return SHADERPORT_SOURCE_DIR; }

}  // namespace shaderport::testing
