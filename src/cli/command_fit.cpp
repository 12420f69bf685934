// frictionid fit: identify a model's parameters from a dataset and write a report.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <future>
#include <stdexcept>
#include <system_error>

#include <frictionid/fit_error.hpp>
#include <frictionid/io/dataset_csv.hpp>
#include <frictionid/io/input_error.hpp>
#include <frictionid/io/pressure_map_reader.hpp>
#include <frictionid/io/report_writer.hpp>
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

int run_fit(const app::FitRequest& o) {
  using seconds = std::chrono::duration<double>;
  (void)app::fit_settings(o, o.model);  // bad options fail before the data are read
  if (o.report.empty()) throw InputError("fit needs --report DIR");
  const std::atomic<bool>* interrupted = install_interrupt_handler();
  // Reading, fitting and plotting share --threads (identify/thread_budget.hpp).
  ThreadBudget budget(o.threads);
  const ThreadBudgetScope budget_scope(&budget);
  // Held for the whole run, so that two fits into one directory cannot interleave.
  const ReportDirectoryLock lock(o.report, /*wait=*/!o.no_wait, say_waiting_for(o.report),
                                 interrupt_check());
  check_report_directory_replaceable(o.report);
  const auto t_read = std::chrono::steady_clock::now();
  const LoadedDataset loaded = app::load_fit_data(o, o.data);
  const Dataset& data = loaded.data;
  const double read_s = seconds(std::chrono::steady_clock::now() - t_read).count();
  const FitSettings s = app::fit_settings(o, o.model, data);
  ReportOptions report_options;
  report_options.contact = contact_spot_label(s.contact);
  report_options.plot_x = o.plot_x;
  report_options.color_by = o.color_by;
  report_options.threads = o.threads;
  report_options.stop = interrupt_check();
  // Hashed while the fit starts (its global stage runs on one thread); waited for before the
  // report. Any way out of this function waits for it too (the future's destructor).
  std::future<Provenance> provenance = app::report_provenance_async(o, {o.data});
  try {
    check_report_columns(data, report_options);  // before the fit, not after it
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }

  FitResult r;
  try {
    TerminalObserver observer(interrupted, show_progress(o.progress));
    r = app::fit_dataset(s, data, &observer);
  } catch (const FitError& e) {
    std::error_code ec;
    const bool stale = std::filesystem::exists(std::filesystem::path(o.report) / "report.json", ec);
    std::fprintf(
        stderr, "frictionid: fit failed: %s; no report written%s\n",
        text::for_terminal(e.what()).c_str(),
        stale
            ? (" (" + text::for_terminal(o.report) + "/report.json is from an earlier run)").c_str()
            : "");
    return interrupted->load() ? kExitInterrupted : kExitFitFailed;
  }
  if (interrupted->load()) {
    std::fprintf(stderr, "frictionid: interrupted; no report written\n");
    return kExitInterrupted;
  }
  report_options.provenance = provenance.get();
  report_options.provenance.data_form = loaded.form;
  const auto t_write = std::chrono::steady_clock::now();
  const auto files = write_report(o.report, r, data, report_options);
  const double write_s = seconds(std::chrono::steady_clock::now() - t_write).count();

  std::printf("model %s, pressure %s, %s%zu rows, channels", r.model.c_str(),
              text::for_terminal(r.pressure).c_str(),
              report_options.contact == "circle"
                  ? ""
                  : ("contact " + text::for_terminal(report_options.contact) + ", ").c_str(),
              r.rows);
  for (Channel c : r.channels) std::printf(" %s", channel_name(c));
  std::printf("\n");
  for (const auto& p : r.parameters) {
    if (p.fixed)
      std::printf("  %-8s %.10g (fixed)\n", p.name.c_str(), p.value);
    else if (p.std_error)
      std::printf("  %-8s %.10g +- %.3g%s\n", p.name.c_str(), p.value, *p.std_error,
                  p.at_bound ? "  (at bound)" : "");
    else
      std::printf("  %-8s %.10g (not determined)\n", p.name.c_str(), p.value);
  }
  char reduced[32] = "undefined (dof 0)";  // no degree of freedom: see the warning
  if (std::isfinite(r.reduced_chi2)) std::snprintf(reduced, sizeof reduced, "%.6g", r.reduced_chi2);
  std::printf("cost %.6g, reduced chi2 %s, %d of %d starts reached the best, %s in %.2f s\n",
              r.cost, reduced, r.global.reached_best, r.global.starts, r.solver.termination.c_str(),
              r.solver.time_s);
  std::printf(
      "time: reading %.3f s, global stage %.3f s, local fits %.3f s, statistics and predictions "
      "%.3f s, report %.3f s\n",
      read_s, r.solver.global_time_s, r.solver.local_time_s, r.solver.statistics_time_s, write_s);
  for (const auto& w : r.warnings) std::printf("warning: %s\n", text::for_terminal(w).c_str());
  std::printf("report: %s/report.html (%zu files)\n", text::for_terminal(o.report).c_str(),
              files.size());
  return kExitOk;
}

}  // namespace frictionid::cli
