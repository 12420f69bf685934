#include "identify/noise_reweighting.hpp"
#include "identify/local_stage.hpp"
#include "identify/number_text.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <frictionid/fit_error.hpp>

#include "identify/fit_problem.hpp"
#include "identify/log_sum.hpp"
#include "identify/noise_model.hpp"
#include "identify/row_chunks.hpp"

namespace frictionid {
namespace {

// Fitted values of every row (all channels) at x, the rows spread over the problem's threads.
std::array<std::vector<double>, kChannelCount> predictions(const LocalProblem& lp,
                                                           const ParamVector& x) {
  const FitSettings& s = *lp.settings;
  const Dataset& d = *lp.rows.data;
  const ModelEvaluator<double> model(s.model, s.law, x.data(), pass_table(lp, x, false), nullptr,
                                     s.contact);
  std::array<std::vector<double>, kChannelCount> out;
  for (auto& v : out) v.resize(d.rows());
  for_each_chunk(chunk_count(d.rows()), lp.threads, [&](std::size_t c) {
    const std::size_t end = std::min(d.rows(), (c + 1) * kChunkRows);
    for (std::size_t i = c * kChunkRows; i < end; ++i) {
      const auto r = model({d.v_x[i], d.v_y[i], d.omega[i], d.N[i], d.R[i], d.tilt_sign_at(i)});
      out[0][i] = r.T_x;
      out[1][i] = r.T_y;
      out[2][i] = r.M_z;
      out[3][i] = r.M_roll;
      out[4][i] = r.M_tilt;
    }
  });
  return out;
}

std::string describe(const ChannelNoise& n) {
  switch (n.kind) {
    case NoiseModelKind::Relative:
      return "noise model relative: sigma = " + number_text(n.s_rel) + " |fitted|";
    case NoiseModelKind::Affine:
      return "noise model affine: sigma^2 = " + number_text(n.s_abs) + "^2 + (" +
             number_text(n.s_rel) + " fitted)^2";
    case NoiseModelKind::Additive:
      return "noise model additive: sigma = " + number_text(n.s_abs) + " + " +
             number_text(n.s_rel) + " |fitted|";
    default:
      return "noise model constant: sigma = " + number_text(n.s_abs);
  }
}

}  // namespace

bool noise_estimated(const FitSettings& s, const Dataset& data, Channel c) {
  if (s.noise_model == NoiseModelKind::Columns) return false;
  if (s.noise_model == NoiseModelKind::Auto) return !data.has_sigma(c);
  return true;
}

bool noise_pooled(const FitSettings& s, const Dataset& data,
                  const std::vector<ChannelSummary>& channels, std::size_t free) {
  for (const auto& cs : channels)
    if (noise_estimated(s, data, cs.channel) && cs.rows <= free + 2) return true;
  return false;
}

NoiseRefinement refine_noise(const LocalProblem& lp, const LocalOutcome& start, FitResult& res,
                             FitObserver* observer) {
  const FitSettings& s = *lp.settings;
  const Dataset& data = *lp.rows.data;
  NoiseRefinement out;
  out.fit = start;
  std::size_t nobs = 0;
  for (const auto& cs : res.channel_summaries) nobs += cs.rows;
  const std::size_t k = lp.free.size();
  // The residuals of a fit are smaller than the noise by the parameters it absorbed.
  const double dof_factor =
      nobs > k ? static_cast<double>(nobs) / static_cast<double>(nobs - k) : 1.0;

  std::array<ChannelNoise, kChannelCount> noise{}, previous{};
  // What one channel's estimate adds to the totals; summed in channel order below.
  struct ChannelStep {
    double log_det = 0.0, change = 0.0;
    int parameters = 0;
  };
  for (int it = 1; it <= s.noise_iterations; ++it) {
    const auto fitted = predictions(lp, out.fit.x);
    std::vector<ChannelStep> steps(res.channel_summaries.size());
    // The channels are independent: one task each, on the problem's threads.
    for_each_task(steps.size(), lp.threads, [&](std::size_t k) {
      ChannelSummary& cs = res.channel_summaries[k];
      ChannelStep& step = steps[k];
      const Channel c = cs.channel;
      const int ci = static_cast<int>(c);
      auto& sigma = out.sigma[ci];
      if (!noise_estimated(s, data, c)) return;
      // The channel's rows: fitted values y and residuals e, and the largest |y|.
      std::vector<double> y, e;
      y.reserve(cs.rows);
      e.reserve(cs.rows);
      double peak = 0.0;
      for (std::size_t i = 0; i < data.rows(); ++i)
        if (data.present[ci][i]) {
          y.push_back(fitted[ci][i]);
          e.push_back(fitted[ci][i] - data.value[ci][i]);
          peak = std::max(peak, std::fabs(fitted[ci][i]));
        }
      const std::size_t n = y.size();
      const NoiseModelKind kind =
          s.noise_model == NoiseModelKind::Auto ? NoiseModelKind::Auto : s.noise_model;
      noise[ci] = estimate_channel_noise(std::move(y), std::move(e), kind, dof_factor);
      step.parameters = noise_parameters(noise[ci].kind);
      double y2 = 0.0;
      for (std::size_t i = 0; i < data.rows(); ++i)
        if (data.present[ci][i] && peak > 0.0)
          y2 += (fitted[ci][i] / peak) * (fitted[ci][i] / peak);
      // No sigma below kNoiseFreeSigma of the channel's RMS fitted value: a noise-free channel
      // (residuals at rounding) is treated as exact to that level, not as infinitely precise,
      // which would leave the other channels' parameters below the covariance's rank cut.
      const double floor = std::max(
          {kNoiseFreeSigma * peak * std::sqrt(y2 / static_cast<double>(n)), 1e-15 * peak, 1e-300});
      sigma.assign(data.rows(), std::nan(""));
      double largest = 0.0;
      LogSum log_sigma;
      for (std::size_t i = 0; i < data.rows(); ++i)
        if (data.present[ci][i]) {
          sigma[i] = std::max(noise_sigma(noise[ci], fitted[ci][i]), floor);
          log_sigma.add(sigma[i]);
          largest = std::max(largest, sigma[i]);
        }
      step.log_det = 2.0 * log_sigma.sum();
      // The channel's representative sigma: the RMS over its rows, relative to the largest.
      double sum2 = 0.0;
      for (std::size_t i = 0; i < data.rows(); ++i)
        if (data.present[ci][i]) sum2 += (sigma[i] / largest) * (sigma[i] / largest);
      cs.scale = largest * std::sqrt(sum2 / static_cast<double>(cs.rows));
      cs.scale_source = describe(noise[ci]);
      cs.noise = NoiseEstimate{noise[ci].kind,  noise_model_name(noise[ci].kind),
                               noise[ci].s_abs, noise[ci].s_rel,
                               noise[ci].floor, noise[ci].problem};
      // Relative change of the variance function, measured at the channel's typical fitted
      // value (its RMS), where both of the affine model's terms show.
      const double typical = peak * std::sqrt(y2 / static_cast<double>(n));
      const double now = noise_sigma(noise[ci], typical),
                   before = noise_sigma(previous[ci], typical);
      step.change = noise[ci].kind != previous[ci].kind
                        ? 1.0
                        : std::fabs(now - before) / std::max(now, 1e-300);
    });
    double change = 0.0;
    out.log_det = 0.0;
    out.parameters = 0;
    for (const ChannelStep& step : steps) {
      out.log_det += step.log_det;
      out.parameters += step.parameters;
      change = std::max(change, step.change);
    }
    previous = noise;
    res.noise_iterations = it;
    LocalProblem lw = lp;
    lw.rows.sigma = &out.sigma;
    for (Channel c : lw.rows.channels) lw.rows.scale[static_cast<int>(c)] = 1.0;
    const LocalOutcome refit = local_fit(lw, out.fit.x, observer, it, s.noise_iterations);
    if (observer && observer->cancelled()) throw FitError("interrupted");
    if (!std::isfinite(refit.cost))
      throw FitError("the fit weighted by the estimated noise model failed (" + refit.termination +
                     ")");
    out.fit = refit;
    if (it > 1 && change < s.noise_tolerance) break;
  }
  return out;
}

}  // namespace frictionid
