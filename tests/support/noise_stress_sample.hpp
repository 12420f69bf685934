// The replicates of the two-term noise estimator's stress test (tests/identify/noise_model_test.cpp
// on the small ones, experiments/noise_estimator on 1000): replicate r draws a noise law and a
// sample, deterministically in r.
//
// Fitted values from one of three designs: the T_x or the M_z channel of the project's default
// synthetic design (seed model, Hertz pressure; M_z passes near zero), or values log-spread over
// two decades of both signs. n rows in {8, 20, 60, 300, 600, 2000}; s_rel log-uniform in
// [1e-3, 0.1]; s_abs/(s_rel RMS(y)) log-uniform in [1e-2, 1e2], so the floor dominates
// everywhere, nowhere, or below some |y|. Gaussian residuals of the form's sigma.
#pragma once

#include <cmath>
#include <random>
#include <vector>

#include <frictionid/model_variant.hpp>
#include <frictionid/synthetic_data.hpp>

#include "support/noise_brute_force.hpp"

namespace frictionid::test {

struct StressSample {
  std::vector<double> y, e;
  double s_abs = 0.0, s_rel = 0.0;
  int design = 0;
};

inline std::vector<double> stress_design_values(int design, std::size_t n) {
  std::vector<double> y;
  if (design < 2) {
    const auto law = model::PressureLaw<double>::hertz();
    SyntheticDesign d;
    d.rows = std::max<std::size_t>(n, 600);
    const Dataset data = generate_dataset(
        ModelKind::Seed, law, default_parameters(law, 0.85, 1.3, 0.12), d, NoiseSpec{}, 1);
    const auto& v = data.value[design == 0 ? 0 : 2];
    const std::size_t stride = v.size() / n;
    for (std::size_t i = 0; i < n; ++i) y.push_back(v[i * stride]);
  } else {
    for (std::size_t i = 0; i < n; ++i)
      y.push_back((i % 2 ? -1.0 : 1.0) * 100.0 * std::pow(100.0, static_cast<double>(i) / n));
  }
  return y;
}

// The rows of replicate r (cheap: lets a caller skip the sizes it does not want).
inline std::size_t stress_rows(int r) {
  std::mt19937_64 rng(0x5eed0000ULL + static_cast<unsigned long long>(r));
  rng();
  const std::size_t sizes[] = {8, 20, 60, 300, 600, 2000};
  return sizes[rng() % 6];
}

inline StressSample stress_sample(int r, TwoTerm form) {
  std::mt19937_64 rng(0x5eed0000ULL + static_cast<unsigned long long>(r));
  std::uniform_real_distribution<double> u(0.0, 1.0);
  StressSample out;
  out.design = static_cast<int>(rng() % 3);
  const std::size_t sizes[] = {8, 20, 60, 300, 600, 2000};
  const std::size_t n = sizes[rng() % 6];
  out.y = stress_design_values(out.design, n);
  double rms = 0.0;
  for (double v : out.y) rms += v * v;
  rms = std::sqrt(rms / static_cast<double>(n));
  out.s_rel = std::pow(10.0, -3.0 + 2.0 * u(rng));
  out.s_abs = out.s_rel * rms * std::pow(10.0, -2.0 + 4.0 * u(rng));
  NormalStream g(static_cast<std::uint64_t>(r) * 7919 + 17);
  for (double v : out.y) {
    const double sd = form == TwoTerm::Affine ? std::hypot(out.s_abs, out.s_rel * v)
                                              : out.s_abs + out.s_rel * std::fabs(v);
    out.e.push_back(sd * g.next());
  }
  return out;
}

}  // namespace frictionid::test
