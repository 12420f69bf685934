#include "cli/terminal_observer.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>

#include <frictionid/fit_error.hpp>

#include "cli/signals.hpp"
#include "io/text.hpp"

namespace frictionid::cli {

TerminalObserver::TerminalObserver(const std::atomic<bool>* interrupted, bool progress)
    : interrupted_(interrupted),
      progress_(progress),
      // Diagnostics for performance work: Ceres' time breakdown of the final local fit.
      solver_report_(std::getenv("FRICTIONID_CERES_REPORT") != nullptr) {}

TerminalObserver::~TerminalObserver() {
  if (line_shown_) std::fprintf(stderr, "\r%80s\r", "");
}

void TerminalObserver::on_progress(const FitProgress& p) {
  if (!progress_) return;
  line_shown_ = true;
  switch (p.stage) {
    case FitStage::GlobalSearch:
      std::fprintf(stderr, "\rfrictionid: global search %ld/%ld evaluations   ", p.done, p.total);
      break;
    case FitStage::LocalFit:
      std::fprintf(stderr, "\rfrictionid: local fit %d/%d, iteration %ld, cost %.6e   ", p.start,
                   p.starts, p.done, p.cost);
      break;
    case FitStage::ContactTable:
      std::fprintf(stderr, "\rfrictionid: contact table %ld points (of at most %ld)   ", p.done,
                   p.total);
      break;
    case FitStage::ContactRows:
      std::fprintf(stderr, "\rfrictionid: contact integrals %ld/%ld rows   ", p.done, p.total);
      break;
    case FitStage::ModelRows:
      std::fprintf(stderr, "\rfrictionid: model %ld/%ld rows   ", p.done, p.total);
      break;
  }
}

void TerminalObserver::on_log(const std::string& line) {
  if (solver_report_) std::fprintf(stderr, "%s\n", line.c_str());
}

bool run_stoppable(bool progress, const std::string& output,
                   const std::function<void(FitObserver&)>& work) {
  const std::atomic<bool>* interrupted = install_interrupt_handler();
  try {
    TerminalObserver observer(interrupted, show_progress(progress));
    work(observer);
  } catch (const FitError&) {
    if (!interrupted->load()) throw;
    std::fprintf(stderr, "frictionid: interrupted; %s not written\n",
                 text::for_terminal(output).c_str());
    return false;
  }
  return true;
}

}  // namespace frictionid::cli
