// frictionid compare: fit several model variants to the same rows, report them side by side.
#include <cstdio>

#include <frictionid/fit_error.hpp>
#include <frictionid/io/compare_report.hpp>
#include <frictionid/io/dataset_csv.hpp>
#include <frictionid/io/input_error.hpp>
#include <frictionid/model_comparison.hpp>
#include "app/data_input.hpp"
#include "app/fit_request.hpp"
#include "app/report_provenance.hpp"
#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "cli/signals.hpp"
#include "cli/terminal_observer.hpp"
#include "identify/thread_budget.hpp"
#include "io/report_directory_lock.hpp"
#include "io/report_transaction.hpp"
#include "io/text.hpp"

namespace frictionid::cli {

int run_compare(const app::CompareRequest& o) {
  std::vector<FitSettings> settings;
  for (const auto& name : o.models) {
    if (!parse_model_kind(name))
      throw InputError("--models: unknown model '" + name + "' (expected seed, corrected, exact)");
    settings.push_back(app::fit_settings(o.fit, name, /*lenient=*/true));
  }
  if (o.fit.report.empty()) throw InputError("compare needs --report DIR");
  const std::atomic<bool>* interrupted = install_interrupt_handler();
  // Reading, fitting and plotting share --threads (identify/thread_budget.hpp).
  ThreadBudget budget(o.fit.threads);
  const ThreadBudgetScope budget_scope(&budget);
  // Held for the whole run, so that two runs into one directory cannot interleave.
  const ReportDirectoryLock lock(o.fit.report, /*wait=*/!o.fit.no_wait,
                                 say_waiting_for(o.fit.report));
  check_report_directory_replaceable(o.fit.report);
  const LoadedDataset loaded = app::load_fit_data(o.fit, o.fit.data);
  const Dataset& data = loaded.data;
  for (const FitSettings& s : settings) app::check_rolling_direction(s, data);
  ModelComparison c;
  try {
    TerminalObserver observer(interrupted, show_progress(o.fit.progress));
    c = compare_models(data, settings, &observer);
  } catch (const FitError& e) {
    std::fprintf(stderr, "frictionid: compare failed: %s; no report written\n",
                 text::for_terminal(e.what()).c_str());
    return interrupted->load() ? kExitInterrupted : kExitFitFailed;
  } catch (const std::invalid_argument& e) {
    throw InputError(o.fit.data, 0, 0, e.what());
  }
  Provenance provenance = app::report_provenance(o.fit, {o.fit.data});
  provenance.data_form = loaded.form;
  provenance.options["models"] = o.models;
  const auto files = write_compare_report(o.fit.report, c, data, provenance);
  std::printf("%-10s %14s %14s %10s\n", "model", "chi2", "AIC", "dAIC");
  for (std::size_t k = 0; k < c.fits.size(); ++k)
    std::printf("%-10s %14.6g %14.6g %10.4g\n", c.fits[k].model.c_str(), c.fits[k].chi2,
                c.fits[k].aic, c.delta_aic[k]);
  std::printf("preferred by AIC: %s, by BIC: %s\n", c.preferred_by_aic.c_str(),
              c.preferred_by_bic.c_str());
  for (const auto& n : coefficient_notes(c))
    std::printf("note: %s\n", text::for_terminal(n).c_str());
  std::printf("report: %s/compare.md (%zu files)\n", text::for_terminal(o.fit.report).c_str(),
              files.size());
  return kExitOk;
}

}  // namespace frictionid::cli
