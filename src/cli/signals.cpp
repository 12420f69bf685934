#include "cli/signals.hpp"

#include <unistd.h>

#include <csignal>

#include "io/interruption.hpp"

namespace frictionid::cli {

namespace {

std::atomic<bool>* g_interrupted = nullptr;
extern "C" void on_interrupt(int) {
  g_interrupted->store(true);
}

}  // namespace

const std::atomic<bool>* install_interrupt_handler() {
  g_interrupted = &interrupt_flag();
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  std::signal(SIGHUP, on_interrupt);
  return g_interrupted;
}

bool show_progress(bool asked) {
  return asked || ::isatty(STDERR_FILENO);
}

}  // namespace frictionid::cli
