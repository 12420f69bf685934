#include "identify/fit_warnings.hpp"
#include "identify/number_text.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include <frictionid/model/coefficients.hpp>

#include "identify/residual_diagnostics.hpp"

namespace frictionid {
namespace {

// A rank correlation sorts: on large data every k-th measured row (at most ~50,000) tells as
// much about the trend.
constexpr std::size_t kGrowthSampleRows = 50000;

std::string join_names(const std::vector<int>& idx) {
  std::string s;
  for (std::size_t i = 0; i < idx.size(); ++i) {
    if (i) s += i + 1 == idx.size() ? " and " : ", ";
    s += param_names()[idx[i]];
  }
  return s;
}

bool all_zero(const Dataset& data, Channel c) {
  const int ci = static_cast<int>(c);
  for (std::size_t i = 0; i < data.rows(); ++i)
    if (data.present[ci][i] && data.value[ci][i] != 0.0) return false;
  return true;
}

void warn_zero_and_growing_channels(const Dataset& data, FitResult& res) {
  std::string growing, growth_values;
  for (const auto& cs : res.channel_summaries) {
    const int c = static_cast<int>(cs.channel);
    if (all_zero(data, cs.channel)) {
      res.warnings.push_back("every measured value of " + std::string(channel_name(cs.channel)) +
                             " is zero: the channel only asks the model to predict zero there");
      continue;
    }
    // Sigma columns and a noise model that grows with the signal take care of it. Exact fits
    // (noise-free data) leave rounding residuals, which do grow with the values.
    if ((data.has_sigma(cs.channel) && !cs.noise) ||
        (cs.noise && cs.noise->kind != NoiseModelKind::Constant) || cs.rows < 20 ||
        !(cs.rmse > 1e-9 * cs.scale))
      continue;
    std::vector<double> fitted, measured;
    const std::size_t stride = cs.rows / kGrowthSampleRows + 1;
    std::size_t seen = 0;
    for (std::size_t i = 0; i < data.rows(); ++i)
      if (data.present[c][i] && seen++ % stride == 0) {
        fitted.push_back(res.fitted[c][i]);
        measured.push_back(data.value[c][i]);
      }
    const double growth = residual_growth(fitted, measured);
    if (growth <= kResidualGrowthWarning) continue;
    growing += (growing.empty() ? "" : ", ") + std::string(channel_name(cs.channel));
    growth_values += (growth_values.empty() ? "" : ", ") + number_text(growth);
  }
  if (!growing.empty())
    res.warnings.push_back(
        "the residuals of " + growing + " grow with the measured magnitude (rank correlation " +
        growth_values +
        ") but their noise model is constant: the standard errors assume equal noise on every "
        "row and are likely wrong; " +
        (res.noise_model == "auto"
             ? std::string("auto chose the constant model by BIC, so ask for another: "
                           "--noise-model relative, affine or additive, or per-row sigma columns, "
                           "would weight the rows by their noise")
             : std::string("a relative, affine or additive noise model (or auto), or per-row "
                           "sigma columns, would weight the rows by their noise")));
}

// Rows whose whitened residual is beyond 6 sigma: a Gaussian gives one in 5e8, so they are
// outliers, and one of them can inflate its channel's noise estimate until the channel carries
// no weight. The worst is named.
void warn_outliers(const LocalProblem& lp, FitResult& res) {
  const Dataset& d = *lp.rows.data;
  for (Channel c : lp.rows.channels) {
    const int ci = static_cast<int>(c);
    std::size_t count = 0, worst = 0;
    double worst_r = 0.0;
    for (std::size_t i = 0; i < d.rows(); ++i) {
      const double w = lp.rows.inverse_sigma(c, i);
      if (w == 0.0) continue;
      const double r = std::fabs((res.fitted[ci][i] - d.value[ci][i]) * w);
      if (!(r > 6.0)) continue;
      ++count;
      if (r > worst_r) {
        worst_r = r;
        worst = i;
      }
    }
    if (count == 0) continue;
    const std::string where = worst < d.line.size() && d.line[worst] > 0
                                  ? "line " + std::to_string(d.line[worst])
                                  : "row " + std::to_string(worst + 1);
    const std::size_t rows =
        static_cast<std::size_t>(std::count(d.present[ci].begin(), d.present[ci].end(), true));
    // Outliers are few; a tenth of the rows beyond 6 sigma is the model missing the channel.
    if (count >= 5 && 10 * count >= rows) {
      res.warnings.push_back(
          std::to_string(count) + " of " + std::to_string(rows) + " rows of " + channel_name(c) +
          " (" + number_text(100.0 * static_cast<double>(count) / static_cast<double>(rows)) +
          " %) lie beyond 6 sigma of the fit, far more than outliers (a Gaussian gives one in "
          "5e8): the model misses this channel. Check its sign convention, its units and the "
          "columns' names, or compare models; a robust loss would hide the misfit, not fix it");
      continue;
    }
    res.warnings.push_back(
        std::to_string(count) + " row" + (count > 1 ? "s" : "") + " of " + channel_name(c) +
        " lie beyond 6 sigma of the fit; the worst, at " + where + " (" + channel_name(c) + " = " +
        number_text(d.value[ci][worst]) + ", " + number_text(worst_r) +
        " sigma), looks like an outlier: it inflates the channel's noise estimate and takes "
        "weight from the channel. Check that row, or use a robust loss (huber, cauchy, soft_l1)");
  }
}

void warn_undetermined_and_correlated(const LocalProblem& lp, const std::vector<int>& undetermined,
                                      FitResult& res) {
  if (!undetermined.empty()) {
    std::string w = "not determined by the data: " + join_names(undetermined) +
                    " (the Jacobian is rank deficient along a combination of them); no standard "
                    "error is reported for them";
    const bool has_ty = std::find(lp.rows.channels.begin(), lp.rows.channels.end(), Channel::T_y) !=
                        lp.rows.channels.end();
    if (!has_ty)
      w += ". No fitted channel is T_y, the only one that carries b, b_tilde and p0, and h enters "
           "the rest only through M_roll and tilt terms";
    res.warnings.push_back(w);
  }
  const std::size_t n = res.correlation_names.size();
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b) {
      const double c = res.correlation[a][b];
      if (std::fabs(c) <= 0.99) continue;
      const std::string na = res.correlation_names[a], nb = res.correlation_names[b];
      std::string w = na + " and " + nb + " are strongly correlated (r = " + number_text(c) +
                      "): the data determine mainly a combination of them";
      if (std::set<std::string>{na, nb} == std::set<std::string>{"h", "kappa"})
        w +=
            "; T_y carries them only as h*kappa, M_roll (h alone) or M_z with a known pressure law "
            "separates them";
      res.warnings.push_back(w);
    }
}

// The closed forms' slope coefficients: where the data inform them, and how far they are from
// what the pressure law implies.
void warn_closed_form_coefficients(const LocalProblem& lp, const ParamVector& x, FitResult& res) {
  const FitSettings& s = *lp.settings;
  if (s.model == ModelKind::Exact) return;
  std::size_t inner = 0, outer = 0;
  for (double e : res.eps) {
    if (e < 1.0) ++inner;
    if (e > 1.0) ++outer;
  }
  auto is_free = [&](int i) {
    return std::find(lp.free.begin(), lp.free.end(), i) != lp.free.end();
  };
  if (inner == 0 && is_free(kA))
    res.warnings.push_back(
        "a is poorly determined: no row has eps = v/(|omega| R) < 1, where the small-slip slope a "
        "acts");
  if (outer == 0 && (is_free(kM) || is_free(kB) || is_free(kBTilde)))
    res.warnings.push_back(
        "m and b are poorly determined: no row has eps > 1, where the small-spin slopes act");
  const auto law_c = model::coefficients(model::law_moments(s.law), x[kKappa]);
  const bool seed = s.model == ModelKind::Seed;
  const std::pair<int, double> implied[] = {
      {kA, law_c.a}, {kM, law_c.m}, {seed ? kB : kBTilde, seed ? law_c.b : law_c.b_tilde}};
  // A difference the standard error explains is no news: warn beyond 3 standard errors.
  for (const auto& [i, v] : implied) {
    const ParameterEstimate* e = res.parameter(param_names()[i]);
    if (!is_free(i) || !e || !e->std_error) continue;
    if (!(std::fabs(x[i] - v) > 3.0 * *e->std_error)) continue;
    res.warnings.push_back(
        std::string(param_names()[i]) + " = " + number_text(x[i]) + " differs from the value " +
        number_text(v) + " that the " + s.law_label + " pressure implies at this fit's kappa = " +
        number_text(x[kKappa]) + " by " + number_text(std::fabs(x[i] - v) / *e->std_error) +
        " standard errors: the closed forms are approximations (errors of tens of percent "
        "near eps = 1, docs/physics.md section 3), so fitted coefficients need not equal the "
        "matched "
        "ones");
  }
}

// A two-term noise estimate that failed its gradient check (§8.10): the rows' weights, and the
// standard errors that rely on them, come from a variance function short of its maximum.
void warn_noise_estimates(FitResult& res) {
  for (const auto& cs : res.channel_summaries)
    if (cs.noise && !cs.noise->problem.empty())
      res.warnings.push_back("the " + cs.noise->model + " noise estimate of " +
                             channel_name(cs.channel) + " is " + cs.noise->problem +
                             "; the weights of its rows and the standard errors may be off");
}

}  // namespace

// A channel the fit explains little of: with an estimated noise model a misfit is absorbed as
// noise (reduced chi² near 1), so only the share of the variation explained tells. Either the
// signal is below the noise, or the model misses it.
void warn_unexplained_channels(FitResult& res) {
  for (const auto& cs : res.channel_summaries)
    if (cs.r2 && *cs.r2 < 0.5)
      res.warnings.push_back(
          "the fit explains " +
          (*cs.r2 > 0.0 ? "only " + number_text(100.0 * *cs.r2) + " %" : std::string("none")) +
          " of the variation of " + channel_name(cs.channel) + " (R^2 = " + number_text(*cs.r2) +
          "): either its signal is below its noise, or the model misses it (a sign convention, "
          "a column that is absent or misspelt such as v_y, or the wrong model)");
}

void add_fit_warnings(const LocalProblem& lp, const ParamVector& x,
                      const std::vector<int>& undetermined, FitResult& res) {
  if (!res.solver.converged)
    res.warnings.push_back("the local solver did not converge (" + res.solver.termination +
                           " after " + std::to_string(res.solver.iterations) +
                           " iterations): the estimates may not be at the optimum");
  if (res.dof == 0)
    res.warnings.push_back(
        "no degree of freedom is left: " + std::to_string(res.residuals) +
        " measured values for as many or more free parameters, so the fit passes through the "
        "data and says nothing of its noise; the reduced chi2 and the standard errors are "
        "undefined (null). Fit more rows or hold parameters fixed");
  warn_zero_and_growing_channels(*lp.rows.data, res);
  warn_noise_estimates(res);
  warn_outliers(lp, res);
  warn_unexplained_channels(res);
  warn_undetermined_and_correlated(lp, undetermined, res);
  // The model-based standard error trusts the noise model; the sandwich does not.
  for (const auto& e : res.parameters)
    if (e.std_error && e.std_error_sandwich && !e.at_bound &&
        std::fabs(*e.std_error_sandwich - *e.std_error) > 0.25 * *e.std_error)
      res.warnings.push_back(
          "the standard error of " + e.name + " from the noise model (" +
          number_text(*e.std_error) + ") and the HC3 sandwich (" +
          number_text(*e.std_error_sandwich) + ") differ by " +
          number_text(100.0 * std::fabs(*e.std_error_sandwich / *e.std_error - 1.0)) +
          " %: the noise model may not describe the data's noise, or the model "
          "misses a shape; the sandwich does not rely on either");
  for (const auto& e : res.parameters)
    if (e.at_bound)
      res.warnings.push_back(e.name + " = " + number_text(e.value) + " is at its " +
                             (e.value - e.lower <= e.upper - e.value ? "lower" : "upper") +
                             " bound; its standard error is not meaningful");
  warn_closed_form_coefficients(lp, x, res);
}

}  // namespace frictionid
