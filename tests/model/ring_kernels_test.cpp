// Ring kernels P, Q, S, U, V, X (docs/physics.md §2) against an independent θ-quadrature, their
// series at small and large k, their limits, continuity across the centre ring k = 1 and the μ-form
// identities near k = 1.
#include <frictionid/model/ring_kernels.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "model/test_support.hpp"

namespace frictionid::model::ring_kernels_test {
namespace {

using testing::gauss_legendre;
using testing::kPi;
using testing::kPiL;

// Kernel order used throughout this file; J = Q + S is checked as well.
enum Kernel { kP = 0, kQ, kS, kJ, kU, kV, kX, kKernelCount };
const char* const kNames[kKernelCount] = {"P", "Q", "S", "J", "U", "V", "X"};

struct Direct {
  std::array<long double, kKernelCount> value{}, l1{};  // integral and integral of |integrand|
};

// ∫_0^{2π} g(sin θ) dθ = 2 ∫_0^π g(cos φ) dφ with θ = π/2 + φ (every integrand depends on sin θ
// and cos²θ = sin²φ only). The near-singular point θ = π/2 (Δ → |1 - k|) is the end φ = 0; the
// integrand's complex singularities sit at φ ≈ ±i|ln k|, so panels are graded geometrically from
// |ln k|/8 and each gets a 24-point Gauss–Legendre rule in long double. All differences that
// cancel near φ = 0, k = 1 are written exactly: 1 - cos φ = 2 sin²(φ/2),
// Δ² = (1 - k)² + 4k sin²(φ/2), k - sin θ = (k - 1) + 2 sin²(φ/2).
template <class F>
Direct integrate_phi(long double k, const F& integrand) {
  std::vector<long double> br = {0.0L};
  const long double d = k > 0 ? std::fabs(std::log(k)) : HUGE_VALL;
  if (d > 0 && d < 1) {
    for (long double x = d / 8; x < 1; x *= 2) br.push_back(x);
  }
  const long double last = br.back();
  const int n = static_cast<int>(std::ceil((kPiL - last) / 0.25L));
  for (int j = 1; j <= n; ++j) br.push_back(last + (kPiL - last) * j / n);
  const auto& gl = gauss_legendre(24);
  Direct out;
  for (std::size_t p = 0; p + 1 < br.size(); ++p) {
    const long double c = 0.5L * (br[p] + br[p + 1]), h = 0.5L * (br[p + 1] - br[p]);
    for (std::size_t i = 0; i < gl.x.size(); ++i) {
      const long double phi = c + h * gl.x[i];
      const auto v = integrand(phi);
      for (int j = 0; j < kKernelCount; ++j) {
        out.value[j] += 2 * h * gl.w[i] * v[j];
        out.l1[j] += 2 * h * gl.w[i] * std::fabs(v[j]);
      }
    }
  }
  return out;
}

Direct direct_kernels(long double k) {
  return integrate_phi(k, [k](long double phi) {
    const long double sh = std::sin(phi / 2), omc = 2 * sh * sh, c = std::cos(phi);
    const long double s2 = std::sin(phi) * std::sin(phi);
    const long double delta = std::sqrt((k - 1) * (k - 1) + 4 * k * sh * sh);
    const long double kmc = (k - 1) + omc;  // k - sin θ
    std::array<long double, kKernelCount> v;
    v[kP] = kmc / delta;
    v[kQ] = s2 / delta;
    v[kS] = -c * kmc / delta;
    v[kJ] = ((1 - k) + k * omc) / delta;  // 1 - k sin θ
    v[kU] = c * s2 / delta;
    v[kV] = c * c * kmc / delta;
    v[kX] = s2 * kmc / delta;
    return v;
  });
}

// μ_n = ∫ sinⁿθ/Δ dθ, n = 0..3 (stored in slots 0..3).
Direct direct_moments(long double k) {
  return integrate_phi(k, [k](long double phi) {
    const long double sh = std::sin(phi / 2), c = std::cos(phi);
    const long double delta = std::sqrt((k - 1) * (k - 1) + 4 * k * sh * sh);
    std::array<long double, kKernelCount> v{};
    v[0] = 1 / delta;
    v[1] = c / delta;
    v[2] = c * c / delta;
    v[3] = c * c * c / delta;
    return v;
  });
}

std::array<double, kKernelCount> as_array(const RingKernels<double>& r) {
  return {r.P, r.Q, r.S, r.Q + r.S, r.U, r.V, r.X};
}

// Series from 1/Δ = Σ kⁿ Pₙ(sin θ) (Legendre generating function; for k > 1 the same in q = 1/k
// after Δ = k Δ(q)) with the angular integrals ∫ sin^{2j}θ dθ = 2π (2j-1)!!/(2j)!!.
// Coefficients of k^0..k^7 (small k) and q^0..q^8 (large k), in units of π.
constexpr double kSmall[kKernelCount][8] = {
    {0, 1, 0, 1.0 / 8, 0, 3.0 / 64, 0, 25.0 / 1024},             // P
    {1, 0, -1.0 / 8, 0, -1.0 / 64, 0, -5.0 / 1024, 0},           // Q
    {1, 0, -3.0 / 8, 0, -5.0 / 64, 0, -35.0 / 1024, 0},          // S
    {2, 0, -1.0 / 2, 0, -3.0 / 32, 0, -5.0 / 128, 0},            // J
    {0, 1.0 / 4, 0, -1.0 / 16, 0, -5.0 / 512, 0, -7.0 / 2048},   // U
    {0, 1.0 / 4, 0, 3.0 / 16, 0, 27.0 / 512, 0, 53.0 / 2048},    // V
    {0, 3.0 / 4, 0, -1.0 / 16, 0, -3.0 / 512, 0, -3.0 / 2048}};  // X
constexpr double kLarge[kKernelCount][9] = {
    {2, 0, -1.0 / 2, 0, -3.0 / 32, 0, -5.0 / 128, 0, -175.0 / 1024},    // P
    {0, 1, 0, -1.0 / 8, 0, -1.0 / 64, 0, -5.0 / 1024, 0},               // Q
    {0, 0, 0, 1.0 / 4, 0, 1.0 / 16, 0, 15.0 / 512, 0},                  // S
    {0, 1, 0, 1.0 / 8, 0, 3.0 / 64, 0, 25.0 / 1024, 0},                 // J
    {0, 0, 1.0 / 4, 0, -1.0 / 16, 0, -5.0 / 512, 0, -7.0 / 2048},       // U
    {1, 0, -1.0 / 8, 0, -9.0 / 64, 0, -45.0 / 1024, 0, -357.0 / 2048},  // V
    {1, 0, -3.0 / 8, 0, 3.0 / 64, 0, 5.0 / 1024, 0, 7.0 / 2048}};       // X

template <std::size_t N>
double series(const double (&c)[N], double x) {
  double s = 0;
  for (std::size_t i = N; i-- > 0;) s = s * x + c[i];
  return kPi * s;
}

std::vector<double> kernel_test_points() {
  std::vector<double> ks = {0.0,      1e-12,    1e-8,     1e-4,  1e-3, 0.01,  0.1,
                            0.3,      0.5,      0.7,      0.9,   0.99, 0.999, 1 - 1e-6,
                            1 - 1e-9, 1 + 1e-9, 1 + 1e-6, 1.001, 1.01, 1.1,   1.5,
                            2.0,      5.0,      10.0,     100.0, 1e3,  1e4,   1e6};
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> lg(-6.0, 6.0);
  for (int i = 0; i < 200; ++i) ks.push_back(std::pow(10.0, lg(rng)));
  std::uniform_real_distribution<double> near(-1e-3, 1e-3);
  for (int i = 0; i < 40; ++i) ks.push_back(1.0 + near(rng));
  return ks;
}

// The kernels agree with direct θ-quadrature to ~1e-14 of the integrand's L1 norm (the best a
// cancelling integral can be known absolutely) over k ∈ [0, 1e6], including k = 1 ± 1e-9.
TEST(RingKernels, MatchDirectThetaQuadratureOverTheWholeRange) {
  for (double k : kernel_test_points()) {
    if (k == 1.0) continue;  // the convenience entry is tested separately at k = 1
    const auto got = as_array(ring_kernels(k));
    const Direct ref = direct_kernels(k);
    for (int j = 0; j < kKernelCount; ++j) {
      EXPECT_NEAR(got[j], static_cast<double>(ref.value[j]),
                  3e-15 * static_cast<double>(ref.l1[j]) + 1e-300)
          << kNames[j] << " k=" << k;
    }
  }
}

// Given the accurate complement m1 = 1 - m, inside/outside are accurate right up to k = 1.
TEST(RingKernels, MatchDirectQuadratureNextToTheCentreRingGivenAnAccurateComplement) {
  for (double d_nominal : {1e-3, 1e-6, 1e-9, 1e-12, 1e-15}) {
    const double k = 1.0 - d_nominal;
    const double d = 1.0 - k;  // exact (Sterbenz), so m1 = d (2 - d) to rounding
    {
      const auto got = as_array(ring_kernels_inside(k, k * k, d * (2.0 - d)));
      const Direct ref = direct_kernels(k);
      for (int j = 0; j < kKernelCount; ++j)
        EXPECT_NEAR(got[j], static_cast<double>(ref.value[j]),
                    3e-15 * static_cast<double>(ref.l1[j]))
            << "inside " << kNames[j] << " 1-k=" << d;
    }
    {
      const double q = k;  // outside: q = 1/k = 1 - d, i.e. k = 1/(1 - d) computed in long double
      const auto got = as_array(ring_kernels_outside(q, q * q, d * (2.0 - d)));
      const Direct ref = direct_kernels(1.0L / static_cast<long double>(q));
      for (int j = 0; j < kKernelCount; ++j)
        EXPECT_NEAR(got[j], static_cast<double>(ref.value[j]),
                    3e-15 * static_cast<double>(ref.l1[j]))
            << "outside " << kNames[j] << " 1-q=" << d;
    }
  }
}

// Relative accuracy where the integrals cancel: against the series for k <= 1e-2.
TEST(RingKernels, FollowTheirSmallKSeriesToFullRelativePrecision) {
  for (double k : {1e-10, 1e-6, 1e-4, 1e-3, 1e-2}) {
    const auto got = as_array(ring_kernels(k));
    for (int j = 0; j < kKernelCount; ++j) {
      const double want = series(kSmall[j], k);
      EXPECT_NEAR(got[j], want, 1e-13 * std::fabs(want)) << kNames[j] << " k=" << k;
    }
  }
}

// ... and for k >= 1e2 in q = 1/k, where S = O(k^-3) and U = O(k^-2) are tiny differences.
TEST(RingKernels, FollowTheirLargeKSeriesToFullRelativePrecision) {
  for (double k : {1e2, 1e3, 1e4, 1e6, 1e10}) {
    const auto got = as_array(ring_kernels(k));
    for (int j = 0; j < kKernelCount; ++j) {
      const double want = series(kLarge[j], 1.0 / k);
      EXPECT_NEAR(got[j], want, 1e-13 * std::fabs(want)) << kNames[j] << " k=" << k;
    }
  }
}

// docs/physics.md §2: P(0)=0, P(∞)=2π, Q(0)=π, Q~π/k, J(0)=2π, J~π/k, S=O(k⁻³).
TEST(RingKernels, HaveTheLimitsOfPhysicsSection2) {
  const auto z = ring_kernels(0.0);
  EXPECT_EQ(z.P, 0.0);
  EXPECT_NEAR(z.Q, kPi, 1e-15 * kPi);
  EXPECT_NEAR(z.Q + z.S, 2 * kPi, 1e-15 * kPi);
  EXPECT_EQ(z.U, 0.0);
  EXPECT_EQ(z.V, 0.0);
  EXPECT_EQ(z.X, 0.0);
  for (double k : {1e8, 1e12, 1e100}) {
    const auto r = ring_kernels(k);
    EXPECT_NEAR(r.P, 2 * kPi, 1e-14) << k;
    EXPECT_NEAR(r.Q * k, kPi, 1e-14) << k;
    EXPECT_NEAR((r.Q + r.S) * k, kPi, 1e-14) << k;
    EXPECT_NEAR(r.S * k * k * k, kPi / 4, 1e-14) << k;  // S·k³ → π/4
    EXPECT_NEAR(r.V, kPi, 1e-14) << k;
    EXPECT_TRUE(std::isfinite(r.U) && std::isfinite(r.X)) << k;
  }
  // S is the only kernel decaying faster than 1/k: S/Q → 0 like k⁻².
  const auto a = ring_kernels(1e3), b = ring_kernels(1e4);
  EXPECT_NEAR((b.S / b.Q) / (a.S / a.Q), 1e-2, 1e-6);
}

// Exactly on the centre ring, Δ = 2 sin(φ/2) and every integrand is elementary:
// P = J = 4, Q = 8/3, S = 4/3, U = 8/15, V = 28/15, X = 32/15 (both branches, m1 clamped).
TEST(RingKernels, TakeTheirExactValuesOnTheCentreRingFromBothSides) {
  const std::array<double, kKernelCount> exact = {4.0,        8.0 / 3,     4.0 / 3,    4.0,
                                                  8.0 / 15.0, 28.0 / 15.0, 32.0 / 15.0};
  const auto in = as_array(ring_kernels_inside(1.0, 1.0, 1e-300));
  const auto out = as_array(ring_kernels_outside(1.0, 1.0, 1e-300));
  for (int j = 0; j < kKernelCount; ++j) {
    EXPECT_NEAR(in[j], exact[j], 1e-14) << "inside " << kNames[j];
    EXPECT_NEAR(out[j], exact[j], 1e-14) << "outside " << kNames[j];
  }
}

// The kernels are continuous at k = 1, with a modulus of continuity ~ δ ln(1/δ) (their
// derivatives carry (1-k²) ln|1-k|): inside at 1-δ and outside at 1/(1-δ) ≈ 1+δ approach each
// other and the exact values above.
TEST(RingKernels, AreContinuousAcrossTheCentreRing) {
  const std::array<double, kKernelCount> exact = {4.0,        8.0 / 3,     4.0 / 3,    4.0,
                                                  8.0 / 15.0, 28.0 / 15.0, 32.0 / 15.0};
  for (double d_nominal : {1e-4, 1e-6, 1e-9, 1e-12, 1e-14}) {
    const double k = 1.0 - d_nominal, d = 1.0 - k, m1 = d * (2.0 - d);
    const auto in = as_array(ring_kernels_inside(k, k * k, m1));
    const auto out = as_array(ring_kernels_outside(k, k * k, m1));
    const double bound = 10.0 * d * (1.0 + std::log(1.0 / d)) + 1e-14;
    for (int j = 0; j < kKernelCount; ++j) {
      EXPECT_NEAR(in[j], out[j], 2 * bound) << kNames[j] << " d=" << d;
      EXPECT_NEAR(in[j], exact[j], bound) << kNames[j] << " d=" << d;
      EXPECT_NEAR(out[j], exact[j], bound) << kNames[j] << " d=" << d;
    }
  }
}

// The convenience entry is documented for any k >= 0, so k = 1 itself must work.
TEST(RingKernels, ConvenienceEntryIsExactOnTheCentreRing) {
  const std::array<double, kKernelCount> exact = {4.0,        8.0 / 3,     4.0 / 3,    4.0,
                                                  8.0 / 15.0, 28.0 / 15.0, 32.0 / 15.0};
  const auto got = as_array(ring_kernels(1.0));
  for (int j = 0; j < kKernelCount; ++j) EXPECT_NEAR(got[j], exact[j], 1e-13) << kNames[j];
}

// docs/physics.md §2 μ forms (k ≤ 1, modulus k; μ_n(k) = μ_n(1/k)/k for k > 1), evaluated in long
// double with the standard library's elliptic integrals (not src's AGM).
std::array<long double, 4> mu_closed(long double k) {
  if (k > 1) {
    auto m = mu_closed(1 / k);
    for (auto& x : m) x /= k;
    return m;
  }
  const long double K = std::comp_ellint_1l(k), E = std::comp_ellint_2l(k);
  const long double k2 = k * k, k4 = k2 * k2;
  return {4 * K, 4 / k * (K - E), 4 / (3 * k2) * ((1 + 2 * k2) * K - (1 + k2) * E),
          4 / (15 * k2 * k) * ((2 + 12 * k2 + k4) * K - (2 + 13 * k2 + 2 * k4) * E)};
}

const std::vector<double> kNearOne = {0.6,     0.8,   0.9,  0.99, 0.999,     0.99999,
                                      1.00001, 1.001, 1.01, 1.1,  1.0 / 0.8, 1.6};

// The μ closed forms of docs/physics.md §2 are the θ-moments ∫ sinⁿθ/Δ near k = 1.
TEST(RingKernels, MuClosedFormsAreTheAngularMomentsNearTheCentreRing) {
  for (double k : kNearOne) {
    const auto mu = mu_closed(k);
    const Direct ref = direct_moments(k);
    for (int n = 0; n < 4; ++n)
      EXPECT_NEAR(static_cast<double>(mu[n]), static_cast<double>(ref.value[n]),
                  1e-12 * static_cast<double>(ref.l1[n]))
          << "mu" << n << " k=" << k;
  }
}

// P = kμ0−μ1, Q = μ0−μ2, S = μ2−kμ1, U = μ1−μ3, V = kμ2−μ3 (X = P − V) near k = 1.
TEST(RingKernels, SatisfyTheMuFormIdentitiesNearTheCentreRing) {
  for (double k : kNearOne) {
    const auto mu = mu_closed(k);
    const long double kl = k;
    const std::array<long double, kKernelCount> want = {
        kl * mu[0] - mu[1],
        mu[0] - mu[2],
        mu[2] - kl * mu[1],
        mu[0] - kl * mu[1],
        mu[1] - mu[3],
        kl * mu[2] - mu[3],
        (kl * mu[0] - mu[1]) - (kl * mu[2] - mu[3])};
    const auto got = as_array(ring_kernels(k));
    const double scale = static_cast<double>(std::fabs(mu[0]) + std::fabs(mu[1]));
    for (int j = 0; j < kKernelCount; ++j)
      EXPECT_NEAR(got[j], static_cast<double>(want[j]), 1e-12 * scale) << kNames[j] << " k=" << k;
  }
}

}  // namespace
}  // namespace frictionid::model::ring_kernels_test
