// How a shimmy run ended (docs/physics.md §10.5), from the extremes of psi: rest (a stick phase
// that holds), limit_cycle (the half peak-to-peak amplitude repeats from cycle to cycle),
// growing (it grows from cycle to cycle, or the fork turned past 90 degrees), duration (none of
// these before the end: holding at psi != 0, still decaying, too few cycles, or irregular).
#pragma once

#include <cmath>
#include <string>
#include <vector>

namespace frictionid::model {

enum class ShimmyOutcome { Rest, LimitCycle, Growing, Duration };

inline const char* outcome_name(ShimmyOutcome o) {
  switch (o) {
    case ShimmyOutcome::Rest:
      return "rest";
    case ShimmyOutcome::LimitCycle:
      return "limit_cycle";
    case ShimmyOutcome::Growing:
      return "growing";
    case ShimmyOutcome::Duration:
      return "duration";
  }
  return "duration";
}

struct PsiExtreme {
  double t, psi;
};

// Why a run ended as `duration` (docs/physics.md §10.5): the contact holds the fork at psi != 0
// while the strut drifts (a stick phase at the end), the oscillation still decays (the last two
// cycles shrank by more than the tolerance), fewer than three cycles to judge, or neither.
enum class DurationDetail { None, Holding, Decaying, FewCycles, Irregular };

inline const char* duration_detail_name(DurationDetail d) {
  switch (d) {
    case DurationDetail::Holding:
      return "holding";
    case DurationDetail::Decaying:
      return "decaying";
    case DurationDetail::FewCycles:
      return "few_cycles";
    case DurationDetail::Irregular:
      return "irregular";
    case DurationDetail::None:
      break;
  }
  return "";
}

struct CycleEstimate {
  ShimmyOutcome outcome = ShimmyOutcome::Duration;
  DurationDetail detail = DurationDetail::FewCycles;  // for Duration
  double amplitude = 0.0;  // half peak-to-peak of psi over the last cycle [rad]
  double frequency = 0.0;  // 1/period over the last cycles [Hz]
  double growth = 0.0;     // amplitude ratio of the last cycle to the one before, minus 1
};

// Amplitudes a_k = |psi_k - psi_{k-1}|/2 of successive extremes (alternately maxima and minima).
// limit_cycle when the last two full cycles change the amplitude by at most `tol` relative each;
// growing when the last two both grew by more than tol. Needs 6 extremes.
inline CycleEstimate classify_cycles(const std::vector<PsiExtreme>& ex, double tol) {
  CycleEstimate c;
  const std::size_t n = ex.size();
  if (n < 2) return c;
  const auto amp = [&](std::size_t k) { return 0.5 * std::fabs(ex[k].psi - ex[k - 1].psi); };
  c.amplitude = amp(n - 1);
  if (n >= 3) c.frequency = 1.0 / (ex[n - 1].t - ex[n - 3].t);
  if (n < 6) return c;
  c.detail = DurationDetail::Irregular;
  const double a0 = amp(n - 5), a1 = amp(n - 3), a2 = amp(n - 1);
  if (!(a0 > 0.0) || !(a1 > 0.0)) return c;
  const double g1 = a1 / a0 - 1.0, g2 = a2 / a1 - 1.0;
  c.growth = g2;
  // The mean period of the last two cycles.
  c.frequency = 2.0 / (ex[n - 1].t - ex[n - 5].t);
  if (std::fabs(g1) <= tol && std::fabs(g2) <= tol)
    c.outcome = ShimmyOutcome::LimitCycle;
  else if (g1 > tol && g2 > tol)
    c.outcome = ShimmyOutcome::Growing;
  else if (g1 < -tol && g2 < -tol)
    c.detail = DurationDetail::Decaying;
  if (c.outcome != ShimmyOutcome::Duration) c.detail = DurationDetail::None;
  return c;
}

}  // namespace frictionid::model
