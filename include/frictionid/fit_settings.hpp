// Everything a fit needs besides the data: model, parameter table, loss, channels, search.
// Start from FitSettings::defaults(model, law, label), change what you need by parameter name,
// and let validate() say what is wrong before a fit does.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <frictionid/dataset.hpp>
#include <frictionid/model/contact_spot.hpp>
#include <frictionid/model/pressure_law.hpp>
#include <frictionid/parameters.hpp>

namespace frictionid {

enum class LossKind { None, Huber, Cauchy, SoftL1 };

// How each channel's measurement noise is modelled (docs/physics.md §8.10). Columns: the sigma
// columns, as given. Constant, Relative, Affine, Additive: that variance function for every
// fitted channel, estimated from the residuals. Auto: the sigma columns where a channel has them,
// else the variance function with the smallest BIC, per channel.
enum class NoiseModelKind { Auto, Constant, Relative, Affine, Additive, Columns };

// The setting's name as the command line and the reports spell it: "auto", "constant",
// "relative", "affine", "additive", "columns".
const char* noise_model_kind_name(NoiseModelKind kind);
// The setting of that name, or nullopt for any other string (exact, lower case).
std::optional<NoiseModelKind> parse_noise_model_kind(const std::string& name);

// Which 95 % interval a report puts first (docs/physics.md §8.12): from the covariance (model),
// from the HC3 sandwich, or from the profile of the cost (asymmetric; refits per step).
enum class IntervalMethod { Model, Sandwich, Profile };

struct ParameterSetting {
  double initial = 0.0;  // used when the global stage is off, and as the fixed value
  double lower = 0.0, upper = 0.0;
  bool fixed = false;
  bool log_scale = false;  // the global stage samples it uniformly in log (positive, wide range)
};

// Bounds that respect docs/physics.md §3 and the pressure's positivity (|h| <= 1 keeps
// sigma0 (1 + h rho cos theta) >= 0); initial values from the pressure law.
std::array<ParameterSetting, kParamCount> default_parameter_settings(
    const model::PressureLaw<double>& law);

struct FitSettings {
  ModelKind model = ModelKind::Seed;
  model::PressureLaw<double> law = model::PressureLaw<double>::hertz();
  std::string law_label = "hertz";
  // The contact spot (docs/physics.md §9). Anything but the circle needs the exact model; its
  // aspect q is params[kQ] (fixed at the spot's q unless freed).
  model::ContactSpot contact;
  std::array<ParameterSetting, kParamCount> params =
      default_parameter_settings(model::PressureLaw<double>::hertz());
  std::vector<Channel> channels;  // empty: every channel some row measures

  LossKind loss = LossKind::None;
  double loss_scale = 1.0;  // in whitened units (sigmas)

  NoiseModelKind noise_model = NoiseModelKind::Auto;
  // Reweighting: estimate the noise, refit with it, until every channel's sigma at its RMS
  // fitted value changes by less than noise_tolerance (relative), at most noise_iterations times.
  int noise_iterations = 30;
  double noise_tolerance = 1e-4;

  IntervalMethod intervals = IntervalMethod::Model;
  // Wild (Rademacher) bootstrap replicates for percentile intervals; 0: none. Seeded by `seed`.
  int bootstrap = 0;

  // Global stage: NLopt over the bounds box, then Ceres from the best distinct points.
  bool global = true;
  std::string global_algorithm = "crs2";  // see global_search.hpp and experiments/global_search
  int starts = 4;                         // local fits from the global stage's best distinct points
  long global_evaluations = 3000;         // objective budget of the global stage
  std::size_t global_subsample = 400;     // rows the global stage sees (deterministic subsample)
  unsigned long long seed = 1;

  int max_iterations = 200;
  double function_tolerance = 1e-15;
  double gradient_tolerance = 1e-15;
  double parameter_tolerance = 1e-13;
  int threads = 0;  // threads for the passes over the rows; 0: every hardware thread

  // The settings of a fit of `model` with pressure `law` (named `label` in reports) on `contact`:
  // default bounds and the initial values the law and the spot imply. On any spot but the circle
  // h_y is free; q starts, and stays, at the spot's aspect.
  static FitSettings defaults(ModelKind model, model::PressureLaw<double> law, std::string label,
                              model::ContactSpot contact = {});

  // The parameters the model reads, in report order (model_parameters of parameters.hpp); h_y
  // joins on the circle when tilt_y (the data measures M_tilt).
  std::vector<int> used_parameters(bool tilt_y = false) const;

  // The setting of parameter `name` ("f", "kappa", ...); throws std::invalid_argument naming the
  // parameter when the name is unknown.
  ParameterSetting& parameter(std::string_view name);
  const ParameterSetting& parameter(std::string_view name) const;
  // Shorthands: hold `name` at `value`; bound it to [lower, upper]; start it at `value`.
  FitSettings& fix(std::string_view name, double value);
  FitSettings& bound(std::string_view name, double lower, double upper);
  FitSettings& start(std::string_view name, double value);

  // True when a fit can run with these settings; otherwise false with the reason in *why (when
  // why is not null), naming the setting or parameter. Fitter::fit calls it too.
  bool validate(std::string* why = nullptr) const;
};

}  // namespace frictionid
