#include "app/batch_fit_run.hpp"

#include <exception>
#include <optional>

#include <frictionid/fitter.hpp>
#include <frictionid/io/dataset_csv.hpp>
#include "app/fit_request.hpp"
#include "app/option_parsers.hpp"

namespace frictionid::app {

SummaryRow fit_batch_run(const BatchRun& run, int threads, FitObserver* observer,
                         const RunFitted& on_fitted, const WarmStart* warm) {
  Dataset data;
  try {
    if (run.file_data) {
      data = select_rows(*run.file_data, run.group_rows);
    } else {
      data = load_dataset_csv(run.path, run.options.columns);
      if (!run.group_rows.empty()) data = select_rows(data, run.group_rows);
    }
  } catch (const std::exception& e) {
    return failed_summary_row(run.label, 0, e.what(), run.covariates);
  }
  auto covariates = dataset_covariates(data);
  covariates.insert(covariates.end(), run.covariates.begin(), run.covariates.end());
  try {
    FitSettings s = fit_settings(run.options, run.options.model);
    s.threads = threads;
    std::optional<FitResult> warm_fit;
    if (warm) warm_fit = fit_warm(s, *warm, data, observer);
    const FitResult r = warm_fit ? std::move(*warm_fit) : Fitter(s).fit(data, observer);
    if (on_fitted) on_fitted(r, data);
    return summary_row(run.label, r, std::move(covariates));
  } catch (const std::exception& e) {
    return failed_summary_row(run.label, data.rows(), e.what(), std::move(covariates));
  }
}

}  // namespace frictionid::app
