// frictionid compare: fit several model variants to the same rows, report them side by side.
#include <algorithm>
#include <cstdio>

#include <frictionid/fit_error.hpp>
#include <frictionid/io/compare_report.hpp>
#include <frictionid/io/dataset_csv.hpp>
#include <frictionid/io/input_error.hpp>
#include <frictionid/model_comparison.hpp>
#include "app/data_input.hpp"
#include "app/fit_request.hpp"
#include "app/option_parsers.hpp"
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
  // Every model on each spot, models first: exact on circle and ellipse:0.7 side by side.
  std::vector<app::FitRequest> variants;
  std::vector<std::string> variant_names, contacts;
  for (const auto& name : o.models) {
    if (!parse_model_kind(name))
      throw InputError("--models: unknown model '" + name + "' (expected seed, corrected, exact)");
    for (const auto& contact : o.contacts) {
      app::FitRequest v = o.fit;
      v.model = name;
      v.contact = contact;
      const std::string label = contact_label(contact);
      if (label != "circle" && name != "exact")
        throw InputError("--contact", 0, 0,
                         "'" + label + "' with --models " + name + ": the " + name +
                             " approximant knows the circular spot only; compare spots with "
                             "--models exact");
      (void)app::fit_settings(v, name, /*lenient=*/true);  // before any file is read
      const std::string variant = label == "circle" ? name : name + "@" + label;
      const std::string directory = compare_variant_directory(variant);
      for (const auto& other : variant_names)
        if (compare_variant_directory(other) == directory)
          throw InputError("--contact", 0, 0,
                           "'" + other + "' and '" + variant +
                               "' would share the report directory " + directory +
                               "; give each spot once");
      variants.push_back(std::move(v));
      variant_names.push_back(variant);
      contacts.push_back(label);
    }
  }
  if (o.fit.report.empty()) throw InputError("compare needs --report DIR");
  const std::atomic<bool>* interrupted = install_interrupt_handler();
  // Reading, fitting and plotting share --threads (identify/thread_budget.hpp).
  ThreadBudget budget(o.fit.threads);
  const ThreadBudgetScope budget_scope(&budget);
  // Held for the whole run, so that two runs into one directory cannot interleave.
  const ReportDirectoryLock lock(o.fit.report, /*wait=*/!o.fit.no_wait,
                                 say_waiting_for(o.fit.report), interrupt_check());
  check_report_directory_replaceable(o.fit.report);
  const LoadedDataset loaded = app::load_fit_data(o.fit, o.fit.data);
  const Dataset& data = loaded.data;
  std::vector<FitSettings> settings;
  for (const auto& v : variants) settings.push_back(app::fit_settings(v, v.model, data, true));
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
  const bool on_circle_only = o.contacts == std::vector<std::string>{"circle"};
  std::vector<std::string> inputs = {o.fit.data};
  for (const auto& v : variants)
    for (const auto& file : app::request_input_files(v))
      if (std::find(inputs.begin(), inputs.end(), file) == inputs.end()) inputs.push_back(file);
  Provenance provenance = app::report_provenance(o.fit, inputs);
  provenance.data_form = loaded.form;
  provenance.options["models"] = o.models;
  if (!on_circle_only) provenance.options["contacts"] = o.contacts;
  const std::vector<std::string> fit_contacts =
      on_circle_only ? std::vector<std::string>{} : contacts;
  const auto files =
      write_compare_report(o.fit.report, c, data, provenance, fit_contacts, interrupt_check());
  const ModelComparison named = compare_named_variants(c, fit_contacts);
  // Model names are 10 wide, as they always were; a longer MODEL@SPOT widens the column.
  int width = 10;
  for (const auto& f : named.fits)
    width = std::max(width, static_cast<int>(text::for_terminal(f.model).size()));
  std::printf("%-*s %14s %14s %10s\n", width, "model", "chi2", "AIC", "dAIC");
  for (std::size_t k = 0; k < named.fits.size(); ++k)
    std::printf("%-*s %14.6g %14.6g %10.4g\n", width,
                text::for_terminal(named.fits[k].model).c_str(), named.fits[k].chi2,
                named.fits[k].aic, named.delta_aic[k]);
  std::printf("preferred by AIC: %s, by BIC: %s\n",
              text::for_terminal(named.preferred_by_aic).c_str(),
              text::for_terminal(named.preferred_by_bic).c_str());
  for (const auto& n : coefficient_notes(c))
    std::printf("note: %s\n", text::for_terminal(n).c_str());
  std::printf("report: %s/compare.md (%zu files)\n", text::for_terminal(o.fit.report).c_str(),
              files.size());
  return kExitOk;
}

}  // namespace frictionid::cli
