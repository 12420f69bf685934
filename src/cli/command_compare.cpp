// frictionid compare: fit several model variants to the same rows, report them side by side.
#include <cstdio>

#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "cli/fit_options.hpp"
#include "identify/fitter.hpp"
#include "identify/model_comparison.hpp"
#include "io/compare_report.hpp"
#include "io/dataset_csv.hpp"
#include "io/input_error.hpp"
#include "io/option_parsers.hpp"

namespace frictionid::cli {

int run_compare(const CompareOptions& o) {
  std::vector<FitSettings> settings;
  for (const auto& name : parse_name_list("--models", o.models)) {
    if (!parse_model_kind(name))
      throw InputError("--models: unknown model '" + name + "' (expected seed, corrected, exact)");
    settings.push_back(fit_settings_from_options(o.fit, name, /*lenient=*/true));
  }
  const Dataset data = load_dataset_csv(o.fit.data, parse_column_map(o.fit.columns));
  const std::atomic<bool>* interrupted = install_interrupt_handler();
  ModelComparison c;
  try {
    c = compare_models(data, settings, interrupted);
  } catch (const FitError& e) {
    std::fprintf(stderr, "frictionid: compare failed: %s; no report written\n", e.what());
    return interrupted->load() ? kExitInterrupted : kExitFitFailed;
  } catch (const std::invalid_argument& e) {
    throw InputError(o.fit.data, 0, 0, e.what());
  }
  const auto files = write_compare_report(o.fit.report, c, data);
  std::printf("%-10s %14s %14s %10s\n", "model", "chi2", "AIC", "dAIC");
  for (std::size_t k = 0; k < c.fits.size(); ++k)
    std::printf("%-10s %14.6g %14.6g %10.4g\n", c.fits[k].model.c_str(), c.fits[k].chi2,
                c.fits[k].aic, c.delta_aic[k]);
  std::printf("preferred by AIC: %s, by BIC: %s\n", c.preferred_by_aic.c_str(),
              c.preferred_by_bic.c_str());
  for (const auto& n : coefficient_notes(c)) std::printf("note: %s\n", n.c_str());
  std::printf("report: %s/compare.md (%zu files)\n", o.fit.report.c_str(), files.size());
  return kExitOk;
}

}  // namespace frictionid::cli
