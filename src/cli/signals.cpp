#include "cli/signals.hpp"

#include <unistd.h>

#include <csignal>
#include <cstdio>

#include "io/text.hpp"

namespace frictionid::cli {

namespace {

// Set from the signal handler: lock-free, so that is allowed.
std::atomic<bool> g_interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free);

extern "C" void on_interrupt(int) {
  g_interrupted.store(true);
}

}  // namespace

std::function<bool()> interrupt_check() {
  return [] { return g_interrupted.load(); };
}

const std::atomic<bool>* install_interrupt_handler() {
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  std::signal(SIGHUP, on_interrupt);
  return &g_interrupted;
}

bool show_progress(bool asked) {
  return asked || ::isatty(STDERR_FILENO);
}

std::function<void(const std::string&)> say_waiting_for(const std::string& dir) {
  return [dir](const std::string& lock_file) {
    std::fprintf(stderr,
                 "frictionid: waiting for another run writing report directory %s (lock %s)\n",
                 text::for_terminal(dir).c_str(), text::for_terminal(lock_file).c_str());
  };
}

}  // namespace frictionid::cli
