// The summary table of a campaign (`frictionid batch`, docs/design.md "Contracts added in the
// second wave"): one row per run or group, written as summary.csv and summary.json. It is a pure
// function of its rows, so that any driver (the CLI, the Python scale-out) that fits the same
// runs writes the same bytes.
//
// summary.csv columns, in this order:
//   label, status (ok or failed), rows,
//   per parameter p (canonical order, those any row has): p, p_stderr, p_ci95_lo, p_ci95_hi,
//   cost, reduced_chi2, warnings (count), error,
//   per fitted channel c: noise_<c>_model, noise_<c>_s_abs, noise_<c>_s_rel,
//   covariates in order of first appearance (mean_N, mean_speed, mean_omega_R, then manifest
//   columns and group-by columns).
// A missing value is an empty cell, never NaN; numbers are written with %.17g, so they read back
// bit-identical to the fit's doubles.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include <frictionid/dataset.hpp>
#include <frictionid/fit_result.hpp>

namespace frictionid {

// A covariate's value: a number (means over the rows) or text (a manifest cell, a group value).
struct Covariate {
  std::string name;
  std::variant<double, std::string> value;
};

struct SummaryParameter {
  std::string name;
  double value = 0.0;
  std::optional<double> std_error;
  std::optional<double> ci95_lo, ci95_hi;
};

struct SummaryNoise {
  std::string channel;  // T_x, ...
  std::string model;    // constant, relative, affine; empty when not estimated
  std::optional<double> s_abs, s_rel;
};

struct SummaryRow {
  std::string label;
  bool ok = false;
  std::size_t rows = 0;
  std::vector<SummaryParameter> parameters;  // empty for a failed run
  std::optional<double> cost, reduced_chi2;
  std::vector<std::string> warnings;
  std::string error;  // empty for ok
  std::vector<SummaryNoise> noise;
  std::vector<Covariate> covariates;
};

// The covariates every run has: mean_N, mean_speed (mean of sqrt(v_x^2 + v_y^2)) and
// mean_omega_R (mean of |omega| R). Empty for a dataset without rows.
std::vector<Covariate> dataset_covariates(const Dataset& d);
// Their names, in that order.
std::vector<std::string> dataset_covariate_names();

SummaryRow summary_row(const std::string& label, const FitResult& r,
                       std::vector<Covariate> covariates);
SummaryRow failed_summary_row(const std::string& label, std::size_t rows, const std::string& error,
                              std::vector<Covariate> covariates);

// One row as JSON and back (summary.json's entries; also what a batch journal stores). The
// round trip is exact: doubles are written with enough digits to read back bit-identical.
nlohmann::ordered_json summary_row_json(const SummaryRow& row);
// Keys keep their order (ordered_json), so a row read back writes the same table. Throws
// std::invalid_argument when j is not such an object.
SummaryRow summary_row_from_json(const nlohmann::ordered_json& j);

// The whole table; rows are written in the order given (the batch sorts them by label).
// summary.json is {"count": rows, "failed": failed rows, "runs": [summary_row_json...]}.
std::string summary_csv(const std::vector<SummaryRow>& rows);
nlohmann::ordered_json summary_json(const std::vector<SummaryRow>& rows);

}  // namespace frictionid
