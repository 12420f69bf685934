// The command line's FitObserver: a progress line on stderr (when asked for or on a terminal),
// Ctrl-C as cancellation, and Ceres' full report on stderr when FRICTIONID_CERES_REPORT is set.
#pragma once

#include <atomic>
#include <functional>
#include <string>

#include <frictionid/fit_observer.hpp>

namespace frictionid::cli {

class TerminalObserver : public FitObserver {
 public:
  // interrupted: the flag install_interrupt_handler() returns. progress: print a progress line.
  TerminalObserver(const std::atomic<bool>* interrupted, bool progress);
  ~TerminalObserver() override;  // clears the progress line

  void on_progress(const FitProgress& p) override;
  void on_log(const std::string& line) override;
  bool cancelled() const override { return interrupted_->load(); }

 private:
  const std::atomic<bool>* interrupted_;
  bool progress_;
  bool solver_report_;
  bool line_shown_ = false;
};

// Runs `work` with a TerminalObserver that shows progress when asked or on a terminal and takes
// Ctrl-C as cancellation (eval, generate). False when Ctrl-C stopped it (work's FitError), after
// saying on stderr that `output` was not written; work's other errors pass through.
bool run_stoppable(bool progress, const std::string& output,
                   const std::function<void(FitObserver&)>& work);

}  // namespace frictionid::cli
