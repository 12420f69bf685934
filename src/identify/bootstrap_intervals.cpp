#include "identify/bootstrap_intervals.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <frictionid/fit_error.hpp>

#include "identify/fit_problem.hpp"
#include "identify/local_stage.hpp"
#include "identify/row_chunks.hpp"

namespace frictionid {
namespace {

// SplitMix64: a counter-based generator, so any (seed, replicate, row) has its own sign.
std::uint64_t mix(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

}  // namespace

double bootstrap_percentile(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) throw std::invalid_argument("bootstrap_percentile: no refits");
  const double n = static_cast<double>(sorted.size());
  // 1-based position (B + 1) q; snapped to an integer within rounding so that e.g. 200 * 0.975
  // reads the 195th refit exactly, then clamped to the smallest and largest refit.
  double pos = (n + 1.0) * q;
  if (std::abs(pos - std::round(pos)) < 1e-9 * (n + 1.0)) pos = std::round(pos);
  pos = std::clamp(pos, 1.0, n);
  const auto lo = static_cast<std::size_t>(std::floor(pos));  // 1-based, 1 <= lo <= B
  const std::size_t hi = std::min(lo + 1, sorted.size());
  const double frac = pos - static_cast<double>(lo);
  return sorted[lo - 1] + frac * (sorted[hi - 1] - sorted[lo - 1]);
}

int rademacher_sign(unsigned long long seed, int replicate, std::size_t row) {
  const std::uint64_t h = mix(mix(mix(seed) ^ static_cast<std::uint64_t>(replicate)) ^ row);
  return (h >> 63) ? 1 : -1;
}

void add_bootstrap_intervals(const LocalProblem& lp, const ParamVector& x, int replicates,
                             unsigned long long seed, FitResult& res, FitObserver* observer) {
  if (replicates <= 0 || lp.free.empty()) return;
  const Dataset& data = *lp.rows.data;
  const std::size_t nb = static_cast<std::size_t>(replicates);
  std::vector<ParamVector> estimates(nb);
  std::vector<char> good(nb, 0);
  // Each replicate refits on one thread; the replicates share the threads.
  LocalProblem one = lp;
  one.threads = 1;
  for_each_chunk(nb, lp.threads, [&](std::size_t b) {
    if (observer && observer->cancelled()) return;
    Dataset star = data;
    for (Channel c : lp.rows.channels) {
      const int ci = static_cast<int>(c);
      for (std::size_t i = 0; i < data.rows(); ++i) {
        if (!data.present[ci][i]) continue;
        const double fitted = res.fitted[ci][i];
        const double e = data.value[ci][i] - fitted;
        star.value[ci][i] = fitted + rademacher_sign(seed, static_cast<int>(b), i) * e;
      }
    }
    const LocalProblem pb = problem_on(one, star);
    const LocalOutcome o = local_fit(pb, x, nullptr, 1, 1);
    if (std::isfinite(o.cost)) {
      estimates[b] = o.x;
      good[b] = 1;
    }
  });
  if (observer && observer->cancelled()) throw FitError("interrupted");
  res.bootstrap_replicates = static_cast<int>(std::count(good.begin(), good.end(), 1));
  if (res.bootstrap_replicates < 2) return;
  for (auto& e : res.parameters) {
    if (e.fixed) continue;
    const int i = *param_index(e.name);
    std::vector<double> v;
    for (std::size_t b = 0; b < nb; ++b)
      if (good[b]) v.push_back(estimates[b][i]);
    std::sort(v.begin(), v.end());
    double mean = 0.0;
    for (double t : v) mean += t;
    mean /= static_cast<double>(v.size());
    double ss = 0.0;
    for (double t : v) ss += (t - mean) * (t - mean);
    e.std_error_bootstrap = std::sqrt(ss / static_cast<double>(v.size() - 1));
    e.ci95_bootstrap =
        std::array<double, 2>{bootstrap_percentile(v, 0.025), bootstrap_percentile(v, 0.975)};
  }
}

}  // namespace frictionid
