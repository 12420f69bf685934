// A run of the built executable (FRICTIONID_EXE) that a test signals once it is under way: its
// stderr goes to a file the test watches for the run's progress line, its stdout to /dev/null.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <functional>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace frictionid::test {

using Deadline = std::chrono::steady_clock::time_point;

// Starts FRICTIONID_EXE with `args` (no shell) and returns its pid; -1 when it could not fork or
// FRICTIONID_EXE is not set (a child that cannot exec exits with 127).
inline pid_t start_frictionid(const std::vector<std::string>& args, const std::string& err_file) {
  const char* exe = std::getenv("FRICTIONID_EXE");
  if (!exe) return -1;
  std::vector<char*> argv = {const_cast<char*>(exe)};
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int fd = ::open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, STDERR_FILENO);
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, STDOUT_FILENO);
    ::execv(exe, argv.data());
    ::_exit(127);
  }
  return pid;
}

// Polls `ready` every 20 ms until it holds (true) or the deadline passes (false).
inline bool wait_for(const std::function<bool()>& ready, Deadline deadline) {
  while (!ready()) {
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return true;
}

// Sends `sig` to pid and waits for it to end: its wait status, or nothing when it had not ended
// by the deadline (it is then killed and reaped).
inline std::optional<int> signal_and_wait(pid_t pid, int sig, Deadline deadline) {
  ::kill(pid, sig);
  int status = 0;
  pid_t done = 0;
  while ((done = ::waitpid(pid, &status, WNOHANG)) == 0 &&
         std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  if (done == pid) return status;
  ::kill(pid, SIGKILL);
  ::waitpid(pid, &status, 0);
  return std::nullopt;
}

}  // namespace frictionid::test
