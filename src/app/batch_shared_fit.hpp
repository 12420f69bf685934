// `frictionid batch --shared P[,P]`: after every run's own fit, one joint fit of the runs that
// succeeded, in which the named parameters are common to all (joint_fit.hpp). Writes
// DIR/shared.csv (the summary table's columns, one row per run, at the joint optimum),
// DIR/shared.json (the shared parameters, the joint statistics and the same rows) and
// DIR/shared.html (those rows as summary.html shows the runs' own fits).
#pragma once

#include <string>
#include <vector>

#include <frictionid/fit_observer.hpp>
#include <frictionid/fit_settings.hpp>
#include <frictionid/io/summary_html.hpp>
#include <frictionid/io/summary_table.hpp>
#include "app/batch_runs.hpp"

namespace frictionid::app {

// The parameter names of --shared (none: no joint fit) checked against the request's own settings
// (frictionid::check_shared_parameters); throws InputError before any run is fitted.
void check_shared_option(const std::vector<std::string>& shared, const FitSettings& command_line);

// The same check for every run's settings (a manifest may fix or change the model per run);
// throws InputError naming the run, before any run is fitted. Nothing to check without --shared.
void check_shared_parameters(const std::vector<BatchRun>& runs,
                             const std::vector<std::string>& shared);

// Fits the runs whose row in `table` is ok (the others stay failed rows with their error) and
// writes the three files atomically; `page` is summary.html's options. Throws FitError when the
// joint fit fails, InputError for a shared parameter some run's settings hold fixed or its model
// does not read.
void write_shared_fit(const std::vector<BatchRun>& runs, const std::vector<SummaryRow>& table,
                      const std::vector<std::string>& shared, int threads, FitObserver* observer,
                      const std::string& dir, SummaryHtmlOptions page);

}  // namespace frictionid::app
