// Starts the real shaderport binary as a child process the test can kill,
// limit and wait for (RunShaderport runs it to completion through a shell).
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

namespace shaderport::testing {

struct ChildOptions {
  std::filesystem::path directory;         // working directory
  std::filesystem::path err_file;          // standard error; empty: /dev/null
  rlim_t file_size_limit = RLIM_INFINITY;  // RLIMIT_FSIZE in bytes
};

inline ChildOptions InDirectory(const std::filesystem::path& directory) {
  ChildOptions options;
  options.directory = directory;
  return options;
}

// `shaderport ARGS...` with standard output discarded and SIGXFSZ at its default
// (fatal) disposition; -1 when fork fails.
inline pid_t StartShaderport(const std::vector<std::string>& args, const ChildOptions& options) {
  std::vector<std::string> words{SHADERPORT_BINARY};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  const std::string directory = options.directory.string();
  const std::string err = options.err_file.empty() ? "/dev/null" : options.err_file.string();
  const pid_t pid = ::fork();
  if (pid != 0) return pid;
  // Child: only async-signal-safe calls from here on.
  const int null_fd = ::open("/dev/null", O_RDWR);
  const int err_fd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (null_fd < 0 || err_fd < 0 || ::chdir(directory.c_str()) != 0) ::_exit(126);
  ::dup2(null_fd, STDIN_FILENO);
  ::dup2(null_fd, STDOUT_FILENO);
  ::dup2(err_fd, STDERR_FILENO);
  ::signal(SIGXFSZ, SIG_DFL);
  const rlimit limit{options.file_size_limit, options.file_size_limit};
  if (options.file_size_limit != RLIM_INFINITY && ::setrlimit(RLIMIT_FSIZE, &limit) != 0) {
    ::_exit(126);
  }
  ::execv(argv[0], argv.data());
  ::_exit(127);
}

// The child's exit code, or 128 + the signal that ended it.
inline int WaitForExit(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// True while the child has not exited (it is not reaped).
inline bool StillRunning(pid_t pid) {
  siginfo_t info{};
  return ::waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOHANG | WNOWAIT) == 0 &&
         info.si_pid == 0;
}

}  // namespace shaderport::testing
