// One run of a batch fitted into its summary row. `frictionid batch` calls it on its threads and
// the Python scale-out (python/frictionid/dask.py) on Dask workers, so that both drivers give the
// same rows and hence the same summary table (docs/design.md §4.5).
#pragma once

#include <functional>

#include <frictionid/dataset.hpp>
#include <frictionid/fit_observer.hpp>
#include <frictionid/fit_result.hpp>
#include <frictionid/io/summary_table.hpp>
#include "app/batch_runs.hpp"
#include "app/batch_warm_start.hpp"

namespace frictionid::app {

// Called with a successful fit and its rows, e.g. to write the run's report; what it throws makes
// the run a failed row.
using RunFitted = std::function<void(const FitResult&, const Dataset&)>;

// Reads the run's rows: its group of the loaded file, or its file (then its group_rows of the
// file when it has them without file_data, as a run planned elsewhere does) and fits them with the
// run's options on `threads` threads. A failure of any kind (unreadable file, bad data, failed fit)
// is a failed row carrying the message, never an exception. With `warm`, the fit starts from it
// and falls back to the full search when the warm fit fails its check (batch_warm_start.hpp).
// With `read`, the fingerprint of the bytes the fit read goes there (for the batch journal).
SummaryRow fit_batch_run(const BatchRun& run, int threads, FitObserver* observer,
                         const RunFitted& on_fitted = {}, const WarmStart* warm = nullptr,
                         FileFingerprint* read = nullptr);

}  // namespace frictionid::app
