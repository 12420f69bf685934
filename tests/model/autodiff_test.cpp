// Automatic derivatives (ceres::Jet) of every model variant with respect to every parameter
// (f, kappa, h, a, b, m, n, p0, b_tilde) against fourth-order central differences of the double
// evaluation, and their finiteness at degenerate kinematics (docs/physics.md §5 "Autodiff").
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <frictionid/model/pressure_table.hpp>
#include <frictionid/model_variant.hpp>

namespace frictionid::autodiff_test {
namespace {

using Jet = ceres::Jet<double, kParamCount>;
constexpr double kPi = 3.14159265358979323846;

struct LawCase {
  std::string name;
  model::PressureLaw<double> law;
};

std::vector<LawCase> laws() {
  std::vector<double> rho(41), sigma(41);
  for (int i = 0; i <= 40; ++i) {
    rho[i] = i / 40.0;
    sigma[i] = std::pow((1 - rho[i]) * (1 + rho[i]), 0.7);
  }
  return {{"uniform", model::PressureLaw<double>::uniform()},
          {"hertz", model::PressureLaw<double>::hertz()},
          {"parabolic", model::PressureLaw<double>::parabolic()},
          {"power:1.7", model::PressureLaw<double>::power(1.7)},
          {"power:0.4", model::PressureLaw<double>::power(0.4)},
          {"table", model::PressureLaw<double>::tabulated(
                        std::make_shared<const model::PressureTable>(rho, sigma))},
          {"annulus:0.4", model::PressureLaw<double>::annulus(0.4)},
          {"ring", model::PressureLaw<double>::ring()},
          {"step table",
           model::PressureLaw<double>::tabulated(std::make_shared<const model::PressureTable>(
               std::vector<double>{0.0, 0.5, 0.5, 1.0}, std::vector<double>{2.0, 2.0, 1.0, 0.5}))}};
}

const std::array<ModelKind, 3> kKinds = {ModelKind::Seed, ModelKind::Corrected, ModelKind::Exact};

// Parameters near (not at) the law's matched values, so every derivative is generic.
std::array<double, kParamCount> base_params(const model::PressureLaw<double>& law, double kappa,
                                            double h) {
  auto p = default_parameters(law, 0.6, kappa, h);
  p[kA] *= 1.1;
  p[kB] *= 0.9;
  p[kM] *= 1.05;
  p[kP0] *= 0.95;
  p[kBTilde] *= 1.2;
  return p;
}

std::array<double, 4> channels(const model::Resultants<double>& r) {
  return {r.T_x, r.T_y, r.M_z, r.M_roll};
}
std::array<Jet, 4> channels(const model::Resultants<Jet>& r) {
  return {r.T_x, r.T_y, r.M_z, r.M_roll};
}
const char* const kChannel[4] = {"T_x", "T_y", "M_z", "M_roll"};

std::array<Jet, 4> jet_eval(ModelKind kind, const model::PressureLaw<double>& law,
                            const std::array<double, kParamCount>& p, const model::Kinematics& k) {
  std::array<Jet, kParamCount> pj;
  for (int i = 0; i < kParamCount; ++i) pj[i] = Jet(p[i], i);
  const ModelEvaluator<Jet> ev(kind, law, pj.data());
  return channels(ev(k));
}

std::array<double, 4> double_eval(ModelKind kind, const model::PressureLaw<double>& law,
                                  const std::array<double, kParamCount>& p,
                                  const model::Kinematics& k) {
  const ModelEvaluator<double> ev(kind, law, p.data());
  return channels(ev(k));
}

model::Kinematics kin(double eps, double alpha, double omega, double N, double R) {
  const double v = eps * std::fabs(omega) * R;
  return {v * std::cos(alpha), v * std::sin(alpha), omega, N, R};
}

std::string describe(ModelKind kind, const LawCase& law, const model::Kinematics& k) {
  return std::string(model_name(kind)) + " " + law.name + " v=(" + std::to_string(k.v_x) + "," +
         std::to_string(k.v_y) + ") omega=" + std::to_string(k.omega);
}

void expect_jacobian_matches_differences(ModelKind kind, const LawCase& law,
                                         const std::array<double, kParamCount>& p,
                                         const model::Kinematics& k) {
  const auto jets = jet_eval(kind, law.law, p, k);
  const auto vals = double_eval(kind, law.law, p, k);
  const double F = p[kF] * k.N;
  const double scale[4] = {F, F, F * k.R, k.N * k.R};
  for (int c = 0; c < 4; ++c) EXPECT_NEAR(jets[c].a, vals[c], 1e-14 * scale[c]);
  for (int i = 0; i < kParamCount; ++i) {
    // n only exists for power laws; the table and fixed laws ignore it.
    const double step = 1e-4 * std::max(std::fabs(p[i]), 0.1);
    auto at = [&](double delta) {
      auto q = p;
      q[i] += delta;
      return double_eval(kind, law.law, q, k);
    };
    const auto p1 = at(step), m1 = at(-step), p2 = at(2 * step), m2 = at(-2 * step);
    for (int c = 0; c < 4; ++c) {
      const double fd = (8 * (p1[c] - m1[c]) - (p2[c] - m2[c])) / (12 * step);
      const double ad = jets[c].v[i];
      ASSERT_TRUE(std::isfinite(ad))
          << describe(kind, law, k) << " d" << kChannel[c] << "/d" << param_names()[i];
      EXPECT_NEAR(ad, fd, 1e-6 * std::max(std::fabs(fd), 1e-3 * scale[c]))
          << describe(kind, law, k) << " d" << kChannel[c] << "/d" << param_names()[i];
    }
  }
}

// Kinematics with alpha != 0 and eps both below and above 1 (and the aligned fast paths).
std::vector<model::Kinematics> kinematics() {
  return {kin(0.3, 0.0, 1.2, 5.0, 0.2),  kin(1.6, 0.0, 1.2, 5.0, 0.2),
          kin(3.5, kPi, -0.8, 5.0, 0.2), kin(0.4, 0.7, 1.2, 5.0, 0.2),
          kin(2.5, 2.2, -0.9, 5.0, 0.2), kin(0.05, -1.1, 2.0, 5.0, 0.2),
          kin(30.0, 1.3, 1.0, 5.0, 0.2)};
}

TEST(Autodiff, SeedJacobianMatchesCentralDifferences) {
  for (const LawCase& law : laws())
    for (const auto& k : kinematics()) {
      expect_jacobian_matches_differences(ModelKind::Seed, law, base_params(law.law, 1.4, 0.25), k);
    }
}

TEST(Autodiff, CorrectedJacobianMatchesCentralDifferences) {
  for (const LawCase& law : laws())
    for (const auto& k : kinematics()) {
      expect_jacobian_matches_differences(ModelKind::Corrected, law,
                                          base_params(law.law, 1.4, 0.25), k);
    }
}

TEST(Autodiff, ExactJacobianMatchesCentralDifferences) {
  for (const LawCase& law : laws())
    for (const auto& k : kinematics()) {
      expect_jacobian_matches_differences(ModelKind::Exact, law, base_params(law.law, 1.4, 0.25),
                                          k);
    }
}

// kappa = 1, h = 0: the double model takes the uniform fast path at the centre point, the Jet
// model may not; central differences only evaluate kappa, h != 1, 0, so this compares the Jet
// evaluation's derivatives at the isotropic point with the ring quadrature's.
TEST(Autodiff, ExactJacobianAtTheIsotropicUntiltedPoint) {
  for (const LawCase& law : laws())
    for (const auto& k : {kin(0.3, 0.0, 1.2, 5.0, 0.2), kin(2.0, 0.0, -1.2, 5.0, 0.2)}) {
      expect_jacobian_matches_differences(ModelKind::Exact, law, base_params(law.law, 1.0, 0.0), k);
    }
}

// The exact model reads f, kappa, h (and n for power laws) only.
TEST(Autodiff, ExactModelDoesNotDependOnApproximantCoefficients) {
  for (const LawCase& law : laws()) {
    const auto jets = jet_eval(ModelKind::Exact, law.law, base_params(law.law, 1.4, 0.25),
                               kin(0.7, 0.5, 1.0, 5.0, 0.2));
    for (int c = 0; c < 4; ++c) {
      for (int i : {kA, kB, kM, kP0, kBTilde}) {
        EXPECT_EQ(jets[c].v[i], 0.0) << law.name;
      }
      if (law.law.kind != model::PressureKind::Power) {
        EXPECT_EQ(jets[c].v[kN], 0.0) << law.name;
      }
    }
  }
}

bool all_finite(const std::array<Jet, 4>& j) {
  for (const Jet& x : j) {
    if (!std::isfinite(x.a)) return false;
    for (int i = 0; i < kParamCount; ++i)
      if (!std::isfinite(x.v[i])) return false;
  }
  return true;
}

TEST(Autodiff, DerivativesAreFiniteAtDegenerateKinematics) {
  for (const LawCase& law : laws()) {
    for (ModelKind kind : kKinds) {
      for (double alpha : {0.0, 0.9}) {
        const auto p = base_params(law.law, 1.4, 0.25);
        std::vector<model::Kinematics> ks;
        for (double eps : {0.0, 1e-12, 1e12}) ks.push_back(kin(eps, alpha, 1.5, 5.0, 0.2));
        ks.push_back({0.0, 0.0, 0.0, 5.0, 0.2});  // v = omega = 0
        for (const auto& k : ks) {
          EXPECT_TRUE(all_finite(jet_eval(kind, law.law, p, k)))
              << describe(kind, law, k) << " alpha=" << alpha;
        }
      }
    }
  }
}

// omega = 0 exactly (pure sliding, eps = inf) is an ordinary row of real data.
void expect_finite_under_pure_sliding(ModelKind kind) {
  for (const LawCase& law : laws()) {
    for (double alpha : {0.0, 0.9}) {
      const auto p = base_params(law.law, 1.4, 0.25);
      // omega = 0, and omega so small that eps^2 overflows (eps ~ 1e300)
      for (double omega : {0.0, 1e-300}) {
        const model::Kinematics k{0.3 * std::cos(alpha), 0.3 * std::sin(alpha), omega, 5.0, 0.2};
        EXPECT_TRUE(all_finite(jet_eval(kind, law.law, p, k)))
            << describe(kind, law, k) << " alpha=" << alpha;
      }
    }
  }
}

TEST(Autodiff, ExactDerivativesAreFiniteUnderPureSliding) {
  expect_finite_under_pure_sliding(ModelKind::Exact);
}

TEST(Autodiff, ApproximantDerivativesAreFiniteUnderPureSliding) {
  expect_finite_under_pure_sliding(ModelKind::Seed);
  expect_finite_under_pure_sliding(ModelKind::Corrected);
}

}  // namespace
}  // namespace frictionid::autodiff_test
