// What a running fit tells its caller, and how the caller stops it. The library never writes to
// a stream or reads the environment: a command-line tool, a GUI or a Python binding implements
// this interface and decides what to show.
#pragma once

#include <string>

namespace frictionid {

// Before the search, the exact model on a non-circular spot computes its rows' integrals once
// (docs/physics.md §9.7): ContactTable while it attempts a table of them, ContactRows while it
// integrates or reads the rows. eval and generate report the same ContactTable, then ModelRows
// while the model runs over their rows.
enum class FitStage { GlobalSearch, LocalFit, ContactTable, ContactRows, ModelRows };

struct FitProgress {
  FitStage stage = FitStage::GlobalSearch;
  // global search: evaluations so far; local fit: iterations so far; contact table: its points
  // so far; contact rows, model rows: rows done
  long done = 0;
  // global search: the evaluation budget; local fit: the iteration limit; contact table: its
  // budget of points (the build is abandoned, and the rows integrated, before it would exceed
  // it); contact rows, model rows: the rows
  long total = 0;
  int start = 0;      // local fit: which start (1-based), of `starts`
  int starts = 0;     // local fits in this run (the last one may refine on all rows)
  double cost = 0.0;  // local fit: the current cost
};

class FitObserver {
 public:
  virtual ~FitObserver() = default;
  // Called from the fitting thread every few hundred global evaluations, every local iteration
  // and every few thousand contact points or rows; keep it cheap.
  virtual void on_progress(const FitProgress& /*progress*/) {}
  // Diagnostics a user may want to see, e.g. the solver's full report of the final local fit.
  virtual void on_log(const std::string& /*line*/) {}
  // Polled during the fit; returning true stops it with FitError("interrupted").
  virtual bool cancelled() const { return false; }
};

}  // namespace frictionid
