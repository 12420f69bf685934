// The terminal's side of a long run: Ctrl-C as cancellation and whether to show progress.
#pragma once

#include <atomic>

namespace frictionid::cli {

// SIGINT, SIGTERM and SIGHUP set the returned flag (io/interruption.hpp): fits stop at their next
// evaluation, and the report stage keeps the earlier report.
const std::atomic<bool>* install_interrupt_handler();

// Whether runs show a progress line: asked for, or stderr is a terminal.
bool show_progress(bool asked);

}  // namespace frictionid::cli
