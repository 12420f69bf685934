#include "identify/fit_problem.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "identify/noise_reweighting.hpp"
#include "identify/row_chunks.hpp"

namespace frictionid {
namespace {

// Whether every measured value of c is the same (zero, or a constant): such a channel carries
// no information on its noise, which an estimated noise model would divide by.
bool constant_channel(const Dataset& data, Channel c) {
  const int ci = static_cast<int>(c);
  std::size_t count = 0;
  double v0 = 0.0;
  for (std::size_t i = 0; i < data.rows(); ++i) {
    if (!data.present[ci][i]) continue;
    if (count == 0) v0 = data.value[ci][i];
    if (data.value[ci][i] != v0) return false;
    ++count;
  }
  return count >= 2;
}

// The smallest sigma of c's measured rows when every one of them is too large to weigh
// anything (1/sigma^2 underflows to 0: sigma above about 1e154, or infinite), else nothing.
// Such a channel would sit in the fit with zero weight: listed as fitted, with R^2 0.
std::optional<double> weightless_sigma(const Dataset& data, Channel c) {
  const int ci = static_cast<int>(c);
  if (!data.has_sigma(c)) return std::nullopt;
  double smallest = HUGE_VAL;
  bool any = false;
  for (std::size_t i = 0; i < data.rows(); ++i) {
    if (!data.present[ci][i]) continue;
    const double w = 1.0 / data.sigma[ci][i];
    if (w * w > 0.0) return std::nullopt;
    smallest = std::min(smallest, data.sigma[ci][i]);
    any = true;
  }
  return any ? std::optional<double>(smallest) : std::nullopt;
}

// The channels to fit: the requested ones that some row measures, in canonical order.
std::vector<Channel> fitted_channels(const Dataset& data, const FitSettings& s,
                                     std::vector<std::string>& warnings,
                                     std::vector<Channel>& constant,
                                     std::vector<Channel>& weightless) {
  std::vector<Channel> requested = s.channels;
  if (requested.empty())
    for (Channel c : kAllChannels)
      if (data.has_channel(c)) requested.push_back(c);
  std::vector<Channel> out;
  for (Channel c : kAllChannels) {
    if (std::find(requested.begin(), requested.end(), c) == requested.end()) continue;
    if (c == Channel::M_tilt && s.model != ModelKind::Exact && data.has_channel(c)) {
      warnings.push_back(std::string("channel M_tilt is not fitted: the ") + model_name(s.model) +
                         " approximant has no tilt across the rolling direction (--model exact "
                         "has)");
      continue;
    }
    if (!data.has_channel(c)) {
      warnings.push_back(std::string("channel ") + channel_name(c) +
                         " was requested but no row measures it; it is not fitted");
    } else if (const auto big =
                   noise_estimated(s, data, c) ? std::nullopt : weightless_sigma(data, c)) {
      weightless.push_back(c);
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.3g", *big);
      warnings.push_back(std::string("channel ") + channel_name(c) +
                         " left the fit: its sigma column gives every row zero weight (the "
                         "smallest sigma_" +
                         channel_name(c) + " is " + buf +
                         ", and 1/sigma^2 underflows to 0 above about 1e154), so it cannot "
                         "inform the fit and does not count in the degrees of freedom");
    } else if (noise_estimated(s, data, c) && constant_channel(data, c)) {
      constant.push_back(c);
      warnings.push_back(std::string("every measured value of ") + channel_name(c) +
                         " is the same: the channel says nothing about its noise, so it is not "
                         "fitted and does not count in the degrees of freedom");
    } else {
      out.push_back(c);
    }
  }
  return out;
}

// Whitening scale of a channel for the search: the sigma column, else the median magnitude of
// its measured values, which one wild value cannot inflate (the RMS, if more than half are zero;
// the noise model then replaces it).
// `magnitude` is scratch space, shared by the channels: new memory costs a page fault per 4 KiB.
ChannelSummary channel_summary(const Dataset& data, Channel c, std::vector<double>& magnitude) {
  const int ci = static_cast<int>(c);
  ChannelSummary cs;
  cs.channel = c;
  if (data.has_sigma(c)) {
    cs.rows = static_cast<std::size_t>(std::count_if(
        data.present[ci].begin(), data.present[ci].end(), [](std::uint8_t p) { return p != 0; }));
    cs.scale = 1.0;
    cs.scale_source = "sigma column";
    return cs;
  }
  magnitude.clear();
  for (std::size_t i = 0; i < data.rows(); ++i)
    if (data.present[ci][i]) magnitude.push_back(std::fabs(data.value[ci][i]));
  cs.rows = magnitude.size();
  const auto mid = magnitude.begin() + static_cast<std::ptrdiff_t>(magnitude.size() / 2);
  std::nth_element(magnitude.begin(), mid, magnitude.end());
  const double median = magnitude.empty() ? 0.0 : *mid;
  // The RMS relative to the peak: no overflow near the double range.
  const double peak =
      magnitude.empty() ? 0.0 : *std::max_element(magnitude.begin(), magnitude.end());
  double sum2 = 0.0;
  if (peak > 0.0)
    for (double m : magnitude) sum2 += (m / peak) * (m / peak);
  const double rms =
      peak * std::sqrt(sum2 / static_cast<double>(std::max<std::size_t>(cs.rows, 1)));
  cs.scale = median > 0.0 ? median : rms > 0.0 ? rms : 1.0;
  cs.scale_source = median > 0.0 ? "median magnitude of the measured values (no sigma column)"
                    : rms > 0.0  ? "RMS of the measured values (no sigma column)"
                                 : "1 (all measured values are zero; no sigma column)";
  return cs;
}

}  // namespace

LocalProblem make_fit_problem(const Dataset& data, const FitSettings& s, FitResult& res) {
  std::vector<Channel> constant, weightless;
  res.channels = fitted_channels(data, s, res.warnings, constant, weightless);
  const auto names = [](const std::vector<Channel>& cs) {
    std::string out;
    for (Channel c : cs) out += (out.empty() ? "" : ", ") + std::string(channel_name(c));
    return out;
  };
  if (res.channels.empty() && !weightless.empty())
    throw std::invalid_argument("the sigma columns of " + names(weightless) +
                                " give every row zero weight (sigma above about 1e154): no "
                                "channel is left to fit");
  if (res.channels.empty() && !constant.empty())
    throw std::invalid_argument(
        "every measured value of " + names(constant) +
        " is the same in every row: a constant channel says nothing about its noise, so with an "
        "estimated noise model there is nothing to fit; give sigma columns (--noise-model "
        "columns) or measurements that vary");
  if (res.channels.empty())
    throw std::invalid_argument("no requested channel is measured by any row");
  if (s.noise_model == NoiseModelKind::Columns)
    for (Channel c : res.channels)
      if (!data.has_sigma(c))
        throw std::invalid_argument(std::string("the noise model 'columns' needs a sigma_") +
                                    channel_name(c) + " column for the fitted channel " +
                                    channel_name(c));
  LocalProblem lp;
  lp.rows.data = &data;
  lp.rows.channels = res.channels;
  std::vector<double> scratch;
  scratch.reserve(data.rows());
  for (Channel c : res.channels) {
    res.channel_summaries.push_back(channel_summary(data, c, scratch));
    lp.rows.scale[static_cast<int>(c)] = res.channel_summaries.back().scale;
  }
  lp.rows.begin = 0;
  lp.rows.end = data.rows();
  lp.settings = &s;
  lp.used = s.used_parameters();
  for (int i : lp.used)
    if (!s.params[i].fixed) lp.free.push_back(i);
  lp.threads = resolve_thread_count(s.threads);
  return lp;
}

LocalProblem problem_on(const LocalProblem& p, const Dataset& rows) {
  LocalProblem out = p;
  // Replacement sigmas belong to p's rows: they go along only to a copy of them (bootstrap).
  if (out.rows.sigma && rows.rows() != p.rows.data->rows()) out.rows.sigma = nullptr;
  out.rows.data = &rows;
  out.rows.begin = 0;
  out.rows.end = rows.rows();
  return out;
}

ParamVector initial_parameters(const FitSettings& s) {
  ParamVector x{};
  for (int i = 0; i < kParamCount; ++i)
    x[i] = s.params[i].fixed
               ? s.params[i].initial
               : std::clamp(s.params[i].initial, s.params[i].lower, s.params[i].upper);
  return x;
}

std::string first_nonfinite_row(const LocalProblem& p, const ParamVector& x) {
  const Dataset& d = *p.rows.data;
  const FitSettings& s = *p.settings;
  const ModelEvaluator<double> model(s.model, s.law, x.data(), pass_table(p, x, false),
                                     p.quadrature, s.contact);
  for (std::size_t i = p.rows.begin; i < p.rows.end; ++i) {
    const auto r = model({d.v_x[i], d.v_y[i], d.omega[i], d.N[i], d.R[i], d.tilt_sign_at(i)});
    const double pred[kChannelCount] = {r.T_x, r.T_y, r.M_z, r.M_roll, r.M_tilt};
    for (Channel c : p.rows.channels) {
      const int ci = static_cast<int>(c);
      const double w = p.rows.inverse_sigma(c, i);
      if (w == 0.0) continue;
      const double residual = (pred[ci] - d.value[ci][i]) * w;
      if (std::isfinite(residual * residual)) continue;  // its square enters the cost
      const std::string where =
          (i < d.line.size() && d.line[i] > 0
               ? "line " + std::to_string(d.line[i]) + (d.source.empty() ? "" : " of " + d.source)
               : "row " + std::to_string(i + 1)) +
          ", channel " + channel_name(c) + ": ";
      char buf[64];
      if (!std::isfinite(pred[ci])) {
        std::snprintf(buf, sizeof buf, "the model gives %g", pred[ci]);
        return where + buf;
      }
      std::snprintf(buf, sizeof buf, "%.3g", 1.0 / w);
      return where + "the whitened residual overflows (sigma " + buf + ")";
    }
  }
  return {};
}

}  // namespace frictionid
