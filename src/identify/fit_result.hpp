// What a fit returns: a plain value, written to files by src/io and never recomputed there.
// Quantities that may be unavailable are std::optional (reports print null, never NaN).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "identify/dataset.hpp"

namespace frictionid {

struct ParameterEstimate {
  std::string name;
  double value = 0.0;
  double initial = 0.0;  // the value the local stage started from (best global start)
  double lower = 0.0, upper = 0.0;
  bool fixed = false;
  bool at_bound = false;
  std::optional<double> std_error;            // absent when fixed or not determined
  std::optional<std::array<double, 2>> ci95;  // value -/+ t(0.975, dof) * std_error
};

struct ChannelSummary {
  Channel channel;
  std::size_t rows = 0;        // rows that measure it
  double scale = 1.0;          // the sigma the residuals were divided by (when no sigma column)
  std::string scale_source;    // "sigma column" or how the tool chose the scale
  std::optional<double> rmse;  // in the channel's units
  std::optional<double> r2;
};

struct GlobalSearchSummary {
  std::string algorithm;
  int starts = 0;        // local fits started from the global stage's best points
  int reached_best = 0;  // how many of them ended at the best cost (rel. 1e-8)
  long evaluations = 0;  // objective evaluations in the global stage
  std::size_t subsample_rows = 0;
  bool local_fits_on_subsample = false;  // the starts' local fits ran on the subsample, the
                                         // best of them was then refined on all rows
  unsigned long long seed = 0;
};

struct SolverSummary {
  int iterations = 0;
  std::string termination;  // Ceres' termination type, e.g. CONVERGENCE
  bool converged = false;
  // Wall times; not written to report.json (reports are reproducible), printed by the CLI.
  double time_s = 0.0, global_time_s = 0.0, local_time_s = 0.0, statistics_time_s = 0.0;
};

struct FitResult {
  std::string model;
  std::string pressure;
  std::size_t rows = 0;
  std::vector<Channel> channels;  // fitted channels, in canonical order
  std::vector<ParameterEstimate> parameters;

  // Correlation among the free parameters whose std_error exists (names in that order).
  std::vector<std::string> correlation_names;
  std::vector<std::vector<double>> correlation;

  double cost = 0.0;  // 1/2 sum of squared whitened residuals (Ceres' convention), after loss
  double chi2 = 0.0;  // sum of squared whitened residuals
  std::size_t residuals = 0;
  std::size_t dof = 0;
  double reduced_chi2 = 0.0;
  double aic = 0.0, bic = 0.0;
  bool covariance_scaled_by_reduced_chi2 = false;
  std::string loss = "none";
  std::vector<ChannelSummary> channel_summaries;

  GlobalSearchSummary global;
  SolverSummary solver;
  std::vector<std::string> warnings;

  // Per row, for plots: eps = v/(|omega| R) (+inf for omega = 0) and the fitted predictions.
  std::vector<double> eps;
  std::array<std::vector<double>, kChannelCount> fitted;
};

}  // namespace frictionid
