// Running the built executable (FRICTIONID_EXE) or any shell command line from a test and
// taking what it printed and how it exited.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace frictionid::test {

struct CommandResult {
  int code;         // exit code; -1 when it was killed or could not start
  std::string out;  // what it wrote to stdout (redirect stderr in the command line to see it)
};

// Runs `command_line` with /bin/sh.
inline CommandResult run_command(const std::string& command_line) {
  FILE* p = popen(command_line.c_str(), "r");
  if (!p) return {-1, ""};
  std::string out;
  char buf[4096];
  std::size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
  const int status = pclose(p);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

// Runs FRICTIONID_EXE with `args` (shell words); out holds stdout and stderr together.
inline CommandResult run_frictionid(const std::string& args) {
  const char* exe = std::getenv("FRICTIONID_EXE");
  if (!exe) return {-1, "FRICTIONID_EXE not set"};
  return run_command(std::string(exe) + " " + args + " 2>&1");
}

struct SplitResult {
  int code;
  std::string out;  // stdout
  std::string err;  // stderr
};

// Runs FRICTIONID_EXE with `args` (shell words), taking stdout and stderr apart (stderr through a
// temporary file of this process).
inline SplitResult run_frictionid_split(const std::string& args) {
  const char* exe = std::getenv("FRICTIONID_EXE");
  if (!exe) return {-1, "", "FRICTIONID_EXE not set"};
  const std::filesystem::path err_file =
      std::filesystem::temp_directory_path() / ("frictionid_stderr_" + std::to_string(::getpid()));
  const CommandResult r = run_command(std::string(exe) + " " + args + " 2>" + err_file.string());
  std::ifstream in(err_file);
  std::string err((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::filesystem::remove(err_file);
  return {r.code, r.out, err};
}

}  // namespace frictionid::test
