#include "app/batch_fit_run.hpp"

#include <exception>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <frictionid/fitter.hpp>
#include <frictionid/io/dataset_csv.hpp>
#include "app/data_input.hpp"
#include "app/fit_request.hpp"
#include "app/option_parsers.hpp"

namespace frictionid::app {

namespace {

// Reads the run's file, and in `read` the fingerprint of the bytes read: the planned one while the
// file's size and time are those of the plan, else a new hash. A file that changes while it is
// read is an error (the run is fitted again next time).
Dataset read_run_file(const BatchRun& run, FileFingerprint* read) {
  if (!read) return load_fit_data(run.options, run.path).data;
  const FileFingerprint before = stat_file(run.path);
  const bool as_planned = before.size == run.input.size && before.mtime_ns == run.input.mtime_ns &&
                          !run.input.sha256.empty();
  *read = as_planned ? run.input : fingerprint_file(run.path);
  Dataset data = load_fit_data(run.options, run.path).data;
  const FileFingerprint after = stat_file(run.path);
  if (after.size != before.size || after.mtime_ns != before.mtime_ns ||
      (!as_planned && after.size != read->size))
    throw std::runtime_error(run.path + ": the file changed while it was read");
  return data;
}

// Appends the run's --keep columns to `covariates`; the message when the data lack one, else "".
std::string add_kept_columns(const Dataset& data, const std::vector<std::string>& keep,
                             std::vector<Covariate>& covariates) {
  try {
    const auto kept = kept_columns(data, keep);
    covariates.insert(covariates.end(), kept.begin(), kept.end());
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace

SummaryRow fit_batch_run(const BatchRun& run, int threads, FitObserver* observer,
                         const RunFitted& on_fitted, const WarmStart* warm, FileFingerprint* read) {
  Dataset data;
  try {
    if (run.file_data) {
      data = select_rows(*run.file_data, run.group_rows);
      if (read) *read = run.input;  // the bytes read when the batch was planned
    } else {
      data = read_run_file(run, read);
      if (!run.group_rows.empty()) data = select_rows(data, run.group_rows);
    }
  } catch (const std::exception& e) {
    return failed_summary_row(run.label, 0, e.what(), run.covariates);
  }
  auto covariates = dataset_covariates(data);
  covariates.insert(covariates.end(), run.covariates.begin(), run.covariates.end());
  if (const std::string why = add_kept_columns(data, run.options.keep, covariates); !why.empty())
    return failed_summary_row(run.label, data.rows(), why, std::move(covariates));
  try {
    FitSettings s = fit_settings(run.options, run.options.model, data);
    s.threads = threads;
    check_rolling_direction(s, data);
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
