#include <frictionid/model_comparison.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <tuple>

#include "identify/noise_model.hpp"

#include <frictionid/fitter.hpp>
#include <frictionid/model/coefficients.hpp>

namespace frictionid {
namespace {

// Lag-1 autocorrelation pooled over runs: each run is one curve's values in eps order, and only
// neighbours within a run are pairs; the mean is that of all values.
double lag1_autocorrelation(const std::vector<std::vector<double>>& runs) {
  std::size_t n = 0;
  double sum = 0.0;
  for (const auto& run : runs) {
    n += run.size();
    sum += std::accumulate(run.begin(), run.end(), 0.0);
  }
  if (n < 3) return 0.0;
  const double mean = sum / static_cast<double>(n);
  double num = 0.0, den = 0.0;
  for (const auto& x : runs)
    for (std::size_t i = 0; i < x.size(); ++i) {
      den += (x[i] - mean) * (x[i] - mean);
      if (i + 1 < x.size()) num += (x[i] - mean) * (x[i + 1] - mean);
    }
  return den > 0.0 ? num / den : 0.0;
}

}  // namespace

double collapse_factor(const Dataset& d, Channel c, std::size_t i) {
  const double sx = d.v_x[i] < 0.0 ? -1.0 : 1.0, sw = d.omega[i] < 0.0 ? -1.0 : 1.0;
  switch (c) {
    case Channel::T_x:
      return sx / d.N[i];
    case Channel::T_y:
      return sw / d.N[i];
    case Channel::M_z:
      return sw / (d.N[i] * d.R[i]);
    case Channel::M_roll:
    case Channel::M_tilt:
      return 1.0 / (d.N[i] * d.R[i]);
  }
  return 1.0;
}

namespace {
double v_y_at(const Dataset& d, std::size_t i) {
  return i < d.v_y.size() ? d.v_y[i] : 0.0;  // a dataset built by hand may leave v_y empty
}
}  // namespace

SlipCurve slip_curve(const Dataset& d, std::size_t i) {
  SlipCurve k;
  k.direction = std::llround(std::atan2(v_y_at(d, i), d.v_x[i]) * 1e6);
  k.spin = d.omega[i] < 0.0 ? -1 : 1;
  k.tilt = d.tilt_sign_at(i) < 0.0 ? -1 : 1;
  return k;
}

double mirrored_slip_angle_deg(const Dataset& d, std::size_t i) {
  const double s = d.omega[i] < 0.0 ? -1.0 : 1.0;
  const double deg =
      std::atan2(s * v_y_at(d, i), std::fabs(d.v_x[i])) * (180.0 / 3.14159265358979323846);
  // To 1e-6 degrees, so that one angle written by different rounding of v_x and v_y stays one.
  const double rounded = std::round(deg * 1e6) / 1e6;
  return rounded == 0.0 ? 0.0 : rounded;  // no -0
}

std::vector<double> fit_sigma(const FitResult& r, const Dataset& d, Channel c) {
  const int ci = static_cast<int>(c);
  const std::size_t n = d.rows();
  const ChannelSummary* summary = nullptr;
  for (const auto& s : r.channel_summaries)
    if (s.channel == c) summary = &s;
  if (!summary || r.fitted[ci].size() != n) return {};
  std::vector<double> sigma(n, std::nan(""));
  if (d.has_sigma(c) && d.sigma[ci].size() == n) {
    for (std::size_t i = 0; i < n; ++i)
      if (d.present[ci][i]) sigma[i] = d.sigma[ci][i];
    return sigma;
  }
  if (summary->noise) {
    const NoiseEstimate& e = *summary->noise;
    ChannelNoise noise;
    noise.kind = e.kind;
    noise.s_abs = e.s_abs;
    noise.s_rel = e.s_rel;
    noise.floor = e.floor;
    double peak = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      if (d.present[ci][i]) peak = std::max(peak, std::fabs(r.fitted[ci][i]));
    const double floor = std::max(1e-15 * peak, 1e-300);
    for (std::size_t i = 0; i < n; ++i)
      if (d.present[ci][i]) sigma[i] = std::max(noise_sigma(noise, r.fitted[ci][i]), floor);
    return sigma;
  }
  for (std::size_t i = 0; i < n; ++i)
    if (d.present[ci][i]) sigma[i] = summary->scale;
  return sigma;
}

ModelComparison compare_models(const Dataset& data, const std::vector<FitSettings>& settings,
                               FitObserver* observer) {
  ModelComparison c;
  for (const auto& s : settings) c.fits.push_back(Fitter(s).fit(data, observer));
  double best_aic = INFINITY, best_bic = INFINITY;
  for (const auto& f : c.fits) {
    best_aic = std::min(best_aic, f.aic);
    best_bic = std::min(best_bic, f.bic);
  }
  for (const auto& f : c.fits) {
    c.delta_aic.push_back(f.aic - best_aic);
    c.delta_bic.push_back(f.bic - best_bic);
    if (f.aic == best_aic && c.preferred_by_aic.empty()) c.preferred_by_aic = f.model;
    if (f.bic == best_bic && c.preferred_by_bic.empty()) c.preferred_by_bic = f.model;
  }

  // One noise for every fit: that of the fit preferred by AIC.
  std::size_t best = 0;
  for (std::size_t k = 0; k < c.fits.size(); ++k)
    if (c.fits[k].model == c.preferred_by_aic) {
      best = k;
      break;
    }
  c.common_noise_fit = best;
  std::array<std::vector<double>, kChannelCount> sigma;
  for (const auto& cs : c.fits[best].channel_summaries)
    sigma[static_cast<int>(cs.channel)] = fit_sigma(c.fits[best], data, cs.channel);

  // The rows of each curve (slip_curve, load and radius) in eps order (ties by row index):
  // residual runs along a curve show shape misfits; runs across curves would mix them. Measured
  // kinematics may give nearly every row its own direction or load: when fewer than half the
  // rows share their curve with another, the curves are coarser, of one spin sign, tilt sign
  // and slip direction to the nearest 10 degrees.
  const auto& eps = c.fits.front().eps;
  using CurveKey = std::tuple<SlipCurve, double, double>;
  std::map<CurveKey, std::vector<std::size_t>> curves;
  for (std::size_t i = 0; i < data.rows(); ++i)
    curves[{slip_curve(data, i), data.N[i], data.R[i]}].push_back(i);
  std::size_t shared = 0;
  for (const auto& [key, rows] : curves)
    if (rows.size() > 1) shared += rows.size();
  if (2 * shared < data.rows()) {
    curves.clear();
    constexpr double kTenDegrees = 1e6 * 3.14159265358979323846 / 18;  // micro-radians
    for (std::size_t i = 0; i < data.rows(); ++i) {
      SlipCurve k = slip_curve(data, i);
      k.direction = std::llround(static_cast<double>(k.direction) / kTenDegrees);
      curves[{k, 0.0, 0.0}].push_back(i);
    }
  }
  for (auto& [key, rows] : curves)
    std::stable_sort(rows.begin(), rows.end(), [&](std::size_t a, std::size_t b) {
      return eps.size() == data.rows() && eps[a] < eps[b];
    });
  for (const auto& f : c.fits) {
    std::map<std::string, double> ac;
    double chi2 = 0.0;
    for (const auto& cs : f.channel_summaries) {
      const int ci = static_cast<int>(cs.channel);
      const auto& s = sigma[ci];
      if (s.size() != data.rows() || f.fitted[ci].size() != data.rows()) continue;
      std::vector<std::vector<double>> runs;
      for (const auto& [key, rows] : curves) {
        std::vector<double> run;
        for (std::size_t i : rows) {
          if (!data.present[ci][i] || !(s[i] > 0.0)) continue;
          run.push_back((data.value[ci][i] - f.fitted[ci][i]) / s[i]);
          chi2 += run.back() * run.back();
        }
        runs.push_back(std::move(run));
      }
      ac[channel_name(cs.channel)] = lag1_autocorrelation(runs);
    }
    c.residual_autocorrelation.push_back(ac);
    c.chi2_common.push_back(chi2);
  }

  // The approximants know the circle only: their fitted a, b, m are set beside the exact
  // model's on the circle, never on another spot.
  for (std::size_t k = 0; k < settings.size(); ++k) {
    if (settings[k].model != ModelKind::Exact) continue;
    if (settings[k].contact.kind != model::SpotKind::Circle) continue;
    model::PressureLaw<double> law = settings[k].law;
    double kappa = 1.0;
    for (const auto& p : c.fits[k].parameters) {
      if (p.name == "n") law.n = p.value;
      if (p.name == "kappa") kappa = p.value;
    }
    const auto co = model::coefficients(model::law_moments(law), kappa);
    c.implied_by_exact = {
        {"a", co.a}, {"b", co.b}, {"m", co.m}, {"b_tilde", co.b_tilde}, {"p0", co.p0}};
    break;
  }
  return c;
}

}  // namespace frictionid
