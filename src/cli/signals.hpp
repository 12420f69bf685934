// The terminal's side of a long run: Ctrl-C as cancellation, whether to show progress, and the
// line that says a run waits for another.
#pragma once

#include <atomic>
#include <functional>
#include <string>

namespace frictionid::cli {

// SIGINT, SIGTERM and SIGHUP set the returned flag: fits stop at their next evaluation, and the
// report stage keeps the earlier report.
const std::atomic<bool>* install_interrupt_handler();

// The report stage's stop check (io/stop_check.hpp): whether that flag is set.
std::function<bool()> interrupt_check();

// Whether runs show a progress line: asked for, or stderr is a terminal.
bool show_progress(bool asked);

// What a run says on stderr when it starts waiting for another run's lock on `dir`
// (io/report_directory_lock.hpp's on_wait).
std::function<void(const std::string&)> say_waiting_for(const std::string& dir);

}  // namespace frictionid::cli
