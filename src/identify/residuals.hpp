// Whitened, per-row robustified residuals of a model against a dataset (docs/design.md
// "report.json"): r = (model - measured)/sigma per channel; a robust loss rho acts on each row's
// squared norm s by scaling the row's residuals with sqrt(rho(s)/s), so that the sum of squares is
// sum rho(s_i) (per row, not per residual block). Templated on the scalar type: double or a Ceres
// Jet.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include <frictionid/dataset.hpp>
#include <frictionid/fit_settings.hpp>
#include <frictionid/model_variant.hpp>

namespace frictionid {

// The rows of one residual block, with their whitening already resolved.
struct ResidualRows {
  const Dataset* data = nullptr;
  std::vector<Channel> channels;              // fitted channels (output order per row)
  std::array<double, kChannelCount> scale{};  // per-channel sigma when no sigma column
  std::size_t begin = 0, end = 0;             // rows [begin, end)
  // Sigma columns that replace the dataset's (an estimated noise model's), row for row with
  // data; null, or a channel's empty vector: the dataset's own.
  const std::array<std::vector<double>, kChannelCount>* sigma = nullptr;

  std::size_t residual_count() const { return (end - begin) * channels.size(); }
  // Channel c's sigma column, or null when it is whitened by scale.
  const double* sigma_column(Channel c) const {
    const int ci = static_cast<int>(c);
    if (sigma && !(*sigma)[ci].empty()) return (*sigma)[ci].data();
    return data->has_sigma(c) ? data->sigma[ci].data() : nullptr;
  }
  bool has_sigma(Channel c) const { return sigma_column(c) != nullptr; }
  double inverse_sigma(Channel c, std::size_t row) const {
    const int ci = static_cast<int>(c);
    if (!data->present[ci][row]) return 0.0;  // unmeasured: residual held at 0
    const double* s = sigma_column(c);
    return s ? 1.0 / s[row] : 1.0 / scale[ci];
  }
};

// sqrt(rho(s)/s), written through rho(s)/s so that nothing cancels as s -> 0 (a near-exact
// fit): log(1 + x)/x by its series for small x, and 2c^2 (sqrt(1 + x) - 1)/s = 2/(sqrt(1 + x) + 1).
template <typename T>
T robust_row_factor(const T& s, LossKind loss, double scale) {
  using std::log1p;
  using std::sqrt;
  if (loss == LossKind::None || !(s > 1e-300)) return T(1);
  const double c2 = scale * scale;
  const T x = s / c2;
  T ratio;  // rho(s)/s
  switch (loss) {
    case LossKind::Huber:
      if (s <= c2) return T(1);
      ratio = (T(2 * scale) * sqrt(s) - T(c2)) / s;
      break;
    case LossKind::Cauchy:
      ratio = x < 1e-3 ? T(1) + x * (T(-0.5) + x * (T(1.0 / 3) + x * (T(-0.25) + x * 0.2)))
                       : log1p(x) / x;
      break;
    case LossKind::SoftL1:
      ratio = T(2) / (sqrt(T(1) + x) + T(1));
      break;
    default:
      return T(1);
  }
  return sqrt(ratio);
}

inline double robust_rho(double s, LossKind loss, double scale) {
  const double f = robust_row_factor(s, loss, scale);
  return f * f * s;
}

// Writes the residuals of row i (one per fitted channel) for a model already set up with its
// parameters; returns false if one is not finite (Ceres then rejects the step instead of
// accepting NaN).
template <typename T>
bool row_residuals(const ResidualRows& rows, const ModelEvaluator<T>& model, LossKind loss,
                   double loss_scale, std::size_t i, T* row_out) {
  using std::isfinite;
  const Dataset& d = *rows.data;
  const std::size_t nc = rows.channels.size();
  const model::Kinematics k{d.v_x[i], d.v_y[i], d.omega[i], d.N[i], d.R[i], d.tilt_sign_at(i)};
  // The weights first, all divisions together: they overlap each other and the model, where
  // one per channel between the Jet operations would each stall them.
  double w[kChannelCount];
  for (std::size_t j = 0; j < nc; ++j) w[j] = rows.inverse_sigma(rows.channels[j], i);
  const model::Resultants<T> r = model(k);
  T s = T(0);
  for (std::size_t j = 0; j < nc; ++j) {
    const Channel c = rows.channels[j];
    const int ci = static_cast<int>(c);
    const T& pred = c == Channel::T_x      ? r.T_x
                    : c == Channel::T_y    ? r.T_y
                    : c == Channel::M_z    ? r.M_z
                    : c == Channel::M_roll ? r.M_roll
                                           : r.M_tilt;
    // Unmeasured (weight 0): the residual is held at 0, whatever the missing value holds.
    row_out[j] = d.present[ci][i] ? (pred - d.value[ci][i]) * w[j] : T(0);
    if (loss != LossKind::None) s += row_out[j] * row_out[j];
  }
  if (loss != LossKind::None) {
    const T f = robust_row_factor(s, loss, loss_scale);
    for (std::size_t j = 0; j < nc; ++j) row_out[j] *= f;
  }
  for (std::size_t j = 0; j < nc; ++j)
    if (!isfinite(row_out[j])) return false;
  return true;
}

// Writes residual_count() residuals of rows [begin, end) for a model already set up.
template <typename T>
bool evaluate_residuals(const ResidualRows& rows, const ModelEvaluator<T>& model, LossKind loss,
                        double loss_scale, T* out) {
  const std::size_t nc = rows.channels.size();
  for (std::size_t i = rows.begin; i < rows.end; ++i)
    if (!row_residuals(rows, model, loss, loss_scale, i, out + (i - rows.begin) * nc)) return false;
  return true;
}

// The same for a parameter vector (sets the model up first).
template <typename T>
bool evaluate_residuals(const ResidualRows& rows, ModelKind kind,
                        const model::PressureLaw<double>& law, LossKind loss, double loss_scale,
                        const T* params, T* out) {
  const ModelEvaluator<T> model(kind, law, params);
  return evaluate_residuals(rows, model, loss, loss_scale, out);
}

}  // namespace frictionid
