// What a running fit tells its caller, and how the caller stops it. The library never writes to
// a stream or reads the environment: a command-line tool, a GUI or a Python binding implements
// this interface and decides what to show.
#pragma once

#include <string>

namespace frictionid {

enum class FitStage { GlobalSearch, LocalFit };

struct FitProgress {
  FitStage stage = FitStage::GlobalSearch;
  long done = 0;      // global search: evaluations so far; local fit: iterations so far
  long total = 0;     // global search: the evaluation budget; local fit: the iteration limit
  int start = 0;      // local fit: which start (1-based), of `starts`
  int starts = 0;     // local fits in this run (the last one may refine on all rows)
  double cost = 0.0;  // local fit: the current cost
};

class FitObserver {
 public:
  virtual ~FitObserver() = default;
  // Called from the fitting thread every few hundred global evaluations and every local
  // iteration; keep it cheap.
  virtual void on_progress(const FitProgress& /*progress*/) {}
  // Diagnostics a user may want to see, e.g. the solver's full report of the final local fit.
  virtual void on_log(const std::string& /*line*/) {}
  // Polled during the fit; returning true stops it with FitError("interrupted").
  virtual bool cancelled() const { return false; }
};

}  // namespace frictionid
