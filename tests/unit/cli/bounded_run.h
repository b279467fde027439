// Runs the real shaderport binary with a wall-time limit, an optional address-space
// limit and optionally as an unprivileged user; reports the exit, the time and the
// peak memory (ru_maxrss from wait4) so hostile-input tests can bound all three.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "golden.h"

namespace shaderport::testing {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kSanitizedBuild = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kSanitizedBuild = true;
#else
inline constexpr bool kSanitizedBuild = false;
#endif
#else
inline constexpr bool kSanitizedBuild = false;
#endif

// The wall-time bound of a hostile input: sanitizer builds run about ten times slower.
inline constexpr std::chrono::seconds kBoundedRunTimeLimit{kSanitizedBuild ? 150 : 20};

struct BoundedRunOptions {
  std::filesystem::path directory;                         // working directory
  std::chrono::seconds time_limit = kBoundedRunTimeLimit;  // then the group is SIGKILLed
  rlim_t address_space = rlim_t{2} << 30;                  // RLIMIT_AS; ignored in ASan builds
  bool unprivileged = false;                               // as uid/gid 65534 via setpriv when root
  std::vector<std::string> environment = {};               // extra NAME=VALUE
};

struct BoundedRun {
  int exit_code = -1;  // exit status, or 128 + the signal that ended it
  bool timed_out = false;
  double seconds = 0;
  long max_rss_kib = 0;  // the largest of the process and its reaped children
  std::string out;
  std::string err;
  std::string Printed() const { return out + err; }
};

inline bool RunningAsRoot() { return ::geteuid() == 0; }

inline BoundedRun RunBounded(const std::vector<std::string>& args,
                             const BoundedRunOptions& options) {
  static std::atomic<int> counter = 0;  // runs may be started from several threads
  const std::string stem =
      (std::filesystem::temp_directory_path() /
       ("shaderport-bounded-" + std::to_string(::getpid()) + "-" + std::to_string(counter++)))
          .string();
  const std::string out_file = stem + ".out";
  const std::string err_file = stem + ".err";
  std::vector<std::string> words;
  if (options.unprivileged && RunningAsRoot()) {
    words = {"/usr/bin/setpriv", "--reuid=65534", "--regid=65534", "--clear-groups"};
  }
  words.push_back(SHADERPORT_BINARY);
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  std::vector<std::string> environment = {"NO_COLOR=1"};
  for (char** e = environ; *e != nullptr; ++e) environment.emplace_back(*e);
  environment.insert(environment.end(), options.environment.begin(), options.environment.end());
  std::vector<char*> envp;
  for (std::string& entry : environment) envp.push_back(entry.data());
  envp.push_back(nullptr);
  const std::string directory = options.directory.string();

  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid == 0) {
    // Child: only async-signal-safe calls from here on.
    ::setpgid(0, 0);
    const int null_fd = ::open("/dev/null", O_RDONLY);
    const int out_fd = ::open(out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err_fd = ::open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (null_fd < 0 || out_fd < 0 || err_fd < 0 || ::chdir(directory.c_str()) != 0) ::_exit(126);
    ::dup2(null_fd, STDIN_FILENO);
    ::dup2(out_fd, STDOUT_FILENO);
    ::dup2(err_fd, STDERR_FILENO);
    if (!kSanitizedBuild && options.address_space != RLIM_INFINITY) {
      const rlimit limit{options.address_space, options.address_space};
      if (::setrlimit(RLIMIT_AS, &limit) != 0) ::_exit(126);
    }
    ::execve(argv[0], argv.data(), envp.data());
    ::_exit(127);
  }
  BoundedRun run;
  if (pid < 0) return run;
  ::setpgid(pid, pid);  // also here: no race with the child's own call
  const auto deadline = start + options.time_limit;
  int status = 0;
  rusage usage{};
  for (;;) {
    const pid_t done = ::wait4(pid, &status, WNOHANG, &usage);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) return run;
    if (std::chrono::steady_clock::now() > deadline) {
      run.timed_out = true;
      ::kill(-pid, SIGKILL);
      while (::wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
      }
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.max_rss_kib = usage.ru_maxrss;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  run.out = ReadWholeFile(out_file);
  run.err = ReadWholeFile(err_file);
  std::filesystem::remove(out_file);
  std::filesystem::remove(err_file);
  return run;
}

}  // namespace shaderport::testing
