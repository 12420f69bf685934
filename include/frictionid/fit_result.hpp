// What a fit returns: a plain value, written to files by src/io and never recomputed there.
// Quantities that may be unavailable are std::optional (reports print null, never NaN).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <frictionid/dataset.hpp>
#include <frictionid/fit_settings.hpp>
#include <frictionid/parameters.hpp>

namespace frictionid {

struct ParameterEstimate {
  std::string name;
  double value = 0.0;
  double initial = 0.0;  // the value the local stage started from (best global start)
  double lower = 0.0, upper = 0.0;
  bool fixed = false;
  bool at_bound = false;
  std::optional<double> std_error;  // absent when fixed or not determined
  // The HC3 sandwich standard error: no assumption on the noise (docs/physics.md §8.11).
  std::optional<double> std_error_sandwich;
  std::optional<std::array<double, 2>> ci95;           // value -/+ t(0.975, dof) * std_error
  std::optional<std::array<double, 2>> ci95_sandwich;  // value -/+ t * std_error_sandwich
  // The profile of the cost (intervals = profile): where it rises by t^2 (scaled like the
  // covariance); a side that does not close inside the bounds ends at the bound.
  std::optional<std::array<double, 2>> ci95_profile;
  std::array<bool, 2> profile_closed{true, true};
  // Wild bootstrap (bootstrap > 0): percentile interval and standard deviation of the refits.
  std::optional<std::array<double, 2>> ci95_bootstrap;
  std::optional<double> std_error_bootstrap;
};

// A channel's estimated noise (docs/physics.md §8.10): sigma_i^2 = s_abs^2 + (s_rel y_i)^2 with
// the model's form (constant: s_rel = 0; relative: s_abs = 0 and |y_i| floored), or for the
// additive model sigma_i = s_abs + s_rel |y_i|.
struct NoiseEstimate {
  NoiseModelKind kind = NoiseModelKind::Constant;  // Constant, Relative, Affine or Additive
  std::string model;  // its name: "constant", "relative", "affine", "additive"
  double s_abs = 0.0, s_rel = 0.0;
  double floor = 0.0;  // relative model: the smallest |y| used
  // Why the estimate may not be the likelihood maximum (a two-term model whose gradient check
  // failed, §8.10); empty when it is. A warning repeats it.
  std::string problem;
};

struct ChannelSummary {
  Channel channel;
  std::size_t rows = 0;      // rows that measure it
  double scale = 1.0;        // the sigma the residuals were divided by (RMS over rows when it
                             // varies by row)
  std::string scale_source;  // "sigma column" or how the tool chose the scale
  std::optional<NoiseEstimate> noise;  // when the noise model was estimated
  std::optional<double> rmse;          // in the channel's units
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
  ModelKind model_kind = ModelKind::Seed;
  std::string model;  // model_name(model_kind), for reports
  std::string pressure;
  // The contact spot the fit was made on, as --contact spells it (model::contact_spot_label):
  // "circle", "ellipse:0.7", "rect:Q", "map:FILE". With a fitted aspect (--free q) it still
  // names the spot given; the fitted q is parameter("q").
  std::string contact;
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
  IntervalMethod intervals = IntervalMethod::Model;  // which interval reports show first
  std::string interval_method = "model";             // its name: model, sandwich or profile
  int bootstrap_replicates = 0;                      // refits that entered the bootstrap intervals
  std::string noise_model = "columns";  // the setting: auto, constant, relative, affine, columns
  int noise_iterations = 0;             // reweighted refits (0: sigmas given or not estimated)
  std::string loss = "none";
  std::vector<ChannelSummary> channel_summaries;

  GlobalSearchSummary global;
  SolverSummary solver;
  std::vector<std::string> warnings;

  // Per row, for plots: eps = v/(|omega| R) (+inf for omega = 0) and the fitted predictions.
  std::vector<double> eps;
  std::array<std::vector<double>, kChannelCount> fitted;

  // The estimate of parameter `name` ("f", "kappa", ...), or nullptr when the model has none.
  const ParameterEstimate* parameter(std::string_view name) const {
    for (const auto& p : parameters)
      if (p.name == name) return &p;
    return nullptr;
  }
};

}  // namespace frictionid
