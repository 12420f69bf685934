#include <frictionid/model_comparison.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

#include <frictionid/fitter.hpp>
#include <frictionid/model/coefficients.hpp>

namespace frictionid {
namespace {

double lag1_autocorrelation(const std::vector<double>& x) {
  if (x.size() < 3) return 0.0;
  const double mean = std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size());
  double num = 0.0, den = 0.0;
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

double collapsed_residual(const Dataset& d, Channel c, std::size_t i, double r) {
  return r * collapse_factor(d, c, i);
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

  // Rows ordered by eps (ties by row index): residual runs show shape misfits.
  std::vector<std::size_t> order(data.rows());
  std::iota(order.begin(), order.end(), 0);
  const auto& eps = c.fits.front().eps;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return eps[a] < eps[b]; });
  for (const auto& f : c.fits) {
    std::map<std::string, double> ac;
    for (const auto& cs : f.channel_summaries) {
      const int ci = static_cast<int>(cs.channel);
      std::vector<double> r;
      for (std::size_t i : order) {
        if (!data.present[ci][i]) continue;
        r.push_back(collapsed_residual(data, cs.channel, i, data.value[ci][i] - f.fitted[ci][i]));
      }
      ac[channel_name(cs.channel)] = lag1_autocorrelation(r);
    }
    c.residual_autocorrelation.push_back(ac);
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
