// Cost of one model evaluation (one data row): the exact model on its fast path, on the ring
// quadrature and for a general power law; the closed-form approximants; and one Jacobian row of
// the exact model with automatic derivatives. Each iteration evaluates one point, cycling through
// a fixed set of kinematics so that no result can be hoisted out of the loop.
#include <benchmark/benchmark.h>
#include <ceres/jet.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include <frictionid/model/approximants.hpp>
#include <frictionid/model/coefficients.hpp>
#include <frictionid/model/exact_model.hpp>
#include <frictionid/model_variant.hpp>
#include "model/reference_integrator.hpp"  // tests/: the brute-force 2-D reference

namespace {

using namespace frictionid;

constexpr std::size_t kPoints = 256;  // power of two: index with a mask

// eps log-uniform in [lo, hi]; slip angle 0 (aligned, v_y = 0 exactly) or uniform in (-pi, pi].
std::vector<model::Kinematics> points(double lo, double hi, bool aligned, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::vector<model::Kinematics> ks;
  for (std::size_t i = 0; i < kPoints; ++i) {
    const double eps = lo * std::pow(hi / lo, u01(rng));
    const double omega = (u01(rng) < 0.5 ? -1.0 : 1.0) * (0.5 + u01(rng)), R = 0.1;
    const double v = eps * std::fabs(omega) * R;
    const double alpha = aligned ? 0.0 : M_PI * (2 * u01(rng) - 1);
    ks.push_back(
        {aligned ? v : v * std::cos(alpha), aligned ? 0.0 : v * std::sin(alpha), omega, 100.0, R});
  }
  return ks;
}

template <class Model>
void run(benchmark::State& state, const Model& model, const std::vector<model::Kinematics>& ks) {
  std::size_t i = 0;
  for (auto _ : state) {
    auto r = model(ks[i++ & (kPoints - 1)]);
    benchmark::DoNotOptimize(r);
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_ExactHertzAlignedFastPath(benchmark::State& state) {
  const model::ExactModel<double> m({0.6, 1.3, 0.2}, model::PressureLaw<double>::hertz());
  run(state, m, points(0.01, 2.0, true, 1));
}
BENCHMARK(BM_ExactHertzAlignedFastPath);

void BM_ExactHertzObliqueQuadrature(benchmark::State& state) {
  const model::ExactModel<double> m({0.6, 1.3, 0.2}, model::PressureLaw<double>::hertz());
  run(state, m, points(0.01, 100.0, false, 2));
}
BENCHMARK(BM_ExactHertzObliqueQuadrature);

void BM_ExactPower17General(benchmark::State& state) {
  const model::ExactModel<double> m({0.6, 1.3, 0.2}, model::PressureLaw<double>::power(1.7));
  run(state, m, points(0.01, 100.0, false, 3));
}
BENCHMARK(BM_ExactPower17General);

// The exact model with its ring integrals tabulated (what fits, generate and eval --input use):
// any slip angle; the table is built once outside the timed loop.
void exact_tabulated(benchmark::State& state, const model::PressureLaw<double>& law,
                     unsigned seed) {
  const model::ExactModel<double> m({0.6, 1.3, 0.2}, law,
                                    std::make_shared<const model::RingIntegralTable>(law));
  run(state, m, points(0.01, 100.0, false, seed));
}
BENCHMARK_CAPTURE(exact_tabulated, BM_ExactPower17GeneralTabulated,
                  model::PressureLaw<double>::power(1.7), 3);
BENCHMARK_CAPTURE(exact_tabulated, BM_ExactHertzObliqueTabulated,
                  model::PressureLaw<double>::hertz(), 2);

// Building that table (once per fit with a fixed pressure law).
void BM_RingIntegralTableBuildPower17(benchmark::State& state) {
  const auto law = model::PressureLaw<double>::power(1.7);
  for (auto _ : state) {
    const model::RingIntegralTable t(law);
    benchmark::DoNotOptimize(&t);
  }
}
BENCHMARK(BM_RingIntegralTableBuildPower17)->Unit(benchmark::kMillisecond);

template <model::ApproximantForm Form, bool Aligned>
void BM_Approximant(benchmark::State& state) {
  const auto law = model::PressureLaw<double>::power(1.7);
  const auto mo = model::law_moments(law);
  const auto c = model::coefficients(mo, 1.3);
  const model::ApproximantParams<double> p{
      0.6, 1.3, 0.2, c.a, Form == model::ApproximantForm::Seed ? c.b : c.b_tilde, c.m, c.p0};
  const auto shape = model::approximant_shape(mo);
  const auto ks = points(0.01, 100.0, Aligned, 4);
  std::size_t i = 0;
  for (auto _ : state) {
    auto r = model::approximant_resultants(Form, p, shape, ks[i++ & (kPoints - 1)]);
    benchmark::DoNotOptimize(r);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Approximant<model::ApproximantForm::Seed, false>)->Name("BM_SeedApproximantGeneral");
BENCHMARK(BM_Approximant<model::ApproximantForm::Corrected, false>)
    ->Name("BM_CorrectedApproximantGeneral");
// Slip along x (v_y = 0): the seed's three published formulas.
BENCHMARK(BM_Approximant<model::ApproximantForm::Seed, true>)->Name("BM_SeedApproximantAligned");
BENCHMARK(BM_Approximant<model::ApproximantForm::Corrected, true>)
    ->Name("BM_CorrectedApproximantAligned");

// One Jet component per parameter.
using Jet = ceres::Jet<double, kParamCount>;

std::array<Jet, kParamCount> jet_params(const model::PressureLaw<double>& law) {
  const auto p = default_parameters(law, 0.6, 1.3, 0.2);
  std::array<Jet, kParamCount> pj;
  for (int i = 0; i < kParamCount; ++i) pj[i] = Jet(p[i], i);
  return pj;
}

// One Jacobian row of the exact model, power:1.7 (derivatives in f, kappa, h, n, ...).
void BM_ExactPower17JacobianRow(benchmark::State& state) {
  const auto law = model::PressureLaw<double>::power(1.7);
  const auto pj = jet_params(law);
  const ModelEvaluator<Jet> ev(ModelKind::Exact, law, pj.data());
  run(state, ev, points(0.01, 100.0, false, 5));
}
BENCHMARK(BM_ExactPower17JacobianRow);

// The same row as a fit of the exact model computes it: Jets only as wide as the free
// parameters (f, kappa, h, n for a power law), as identify/local_stage.cpp builds them; by the
// radial quadrature, or from the tabulated integrals with n-slopes (a fit's passes on large
// data).
void exact_fit_jacobian_row(benchmark::State& state, bool tabulated) {
  using Jet4 = ceres::Jet<double, 4>;
  const auto law = model::PressureLaw<double>::power(1.7);
  const auto p = default_parameters(law, 0.6, 1.3, 0.2);
  std::array<Jet4, kParamCount> pj;
  for (int i = 0; i < kParamCount; ++i) pj[i] = Jet4(p[i]);
  int k = 0;
  for (int i : {kF, kKappa, kH, kN}) pj[i] = Jet4(p[i], k++);
  const ModelEvaluator<Jet4> ev(
      ModelKind::Exact, law, pj.data(),
      tabulated ? ring_table_for(ModelKind::Exact, law, p[kN], true) : nullptr);
  run(state, ev, points(0.01, 100.0, false, 5));
}
BENCHMARK_CAPTURE(exact_fit_jacobian_row, BM_ExactPower17FitJacobianRow, false);
BENCHMARK_CAPTURE(exact_fit_jacobian_row, BM_ExactPower17FitJacobianRowTabulated, true);

// The brute-force 2-D integral of the local law (tests/model/reference_integrator.hpp: adaptive
// Gauss-Kronrod in rho and theta, split at the instantaneous centre) at the accuracy the exact
// model reaches (1e-10 of the force scale): what the ring reduction saves per point.
void BM_BruteForceReferencePower17(benchmark::State& state) {
  const auto ks = points(0.01, 100.0, false, 3);
  const auto sigma0 = [](double rho) { return std::pow(1.0 - rho * rho, 1.7); };
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& k = ks[i++ & (kPoints - 1)];
    // Unit radius: the reference works in rho = r/R, so slip velocities are divided by R.
    auto r =
        testing::reference_resultants(sigma0, 1.3, 0.2, k.v_x / k.R, k.v_y / k.R, k.omega, 1e-10);
    benchmark::DoNotOptimize(r);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_BruteForceReferencePower17)->Unit(benchmark::kMillisecond);

// Per parameter set (once per residual-block evaluation, not per row): moments with Jet n.
void BM_ExactPower17JetEvaluatorSetup(benchmark::State& state) {
  const auto law = model::PressureLaw<double>::power(1.7);
  const auto pj = jet_params(law);
  for (auto _ : state) {
    const ModelEvaluator<Jet> ev(ModelKind::Exact, law, pj.data());
    benchmark::DoNotOptimize(&ev);
  }
}
BENCHMARK(BM_ExactPower17JetEvaluatorSetup);

}  // namespace
