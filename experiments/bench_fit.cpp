// Cost per data row of the two passes a local fit repeats every iteration: the autodiff pass
// (residuals, Jacobian, J^T J) and the residual-only pass at a trial point. 100,000 rows of the
// default `generate` design (4 channels, slip along x), one thread unless the name says so;
// every model parameter free (seed: 6, exact hertz: f, kappa, h; exact power:1.7: also n).
// "RowByRow": the closed-form passes with the packet pass turned off (allow_row_packets), as a
// processor without AVX2 or a FRICTIONID_PORTABLE build runs them.
#include <benchmark/benchmark.h>

#include <frictionid/synthetic_data.hpp>
#include "identify/local_stage.hpp"

namespace {

using namespace frictionid;

struct Setup {
  Dataset data;
  FitSettings settings;
  LocalProblem problem;
  ParamVector x{};
};

Setup make_setup(ModelKind kind, const model::PressureLaw<double>& law, int threads) {
  Setup s;
  s.settings.model = kind;
  s.settings.law = law;
  s.settings.params = default_parameter_settings(law);
  auto truth = default_parameters(law, 0.85, 1.3, 0.12);
  SyntheticDesign design;
  design.rows = 100000;
  s.data = generate_dataset(kind, law, truth, design, NoiseSpec{0.01, 0.0, false}, 3);
  s.problem.rows.data = &s.data;
  s.problem.rows.channels = {Channel::T_x, Channel::T_y, Channel::M_z, Channel::M_roll};
  s.problem.rows.scale = {100.0, 10.0, 5.0, 1.0};
  s.problem.rows.begin = 0;
  s.problem.rows.end = s.data.rows();
  s.problem.settings = &s.settings;
  s.problem.free = model_parameters(kind, law.kind);
  s.problem.threads = threads;
  s.x = truth;
  // As the fitter does: a fixed law's ring integrals tabulated once per fit.
  if (kind == ModelKind::Exact && !exponent_free(s.problem))
    s.problem.exact_table = ring_table_for(kind, law, truth[kN], false);
  return s;
}

void normal_equations_pass(benchmark::State& state, ModelKind kind,
                           const model::PressureLaw<double>& law, int threads,
                           bool packets = true) {
  Setup s = make_setup(kind, law, threads);
  allow_row_packets(packets);
  s.problem.settings = &s.settings;
  s.problem.rows.data = &s.data;
  NormalEquations ne;
  for (auto _ : state) {
    benchmark::DoNotOptimize(normal_equations(s.problem, s.x, ne));
    benchmark::DoNotOptimize(ne.rtr);
  }
  allow_row_packets(true);
  state.SetItemsProcessed(state.iterations() * static_cast<long>(s.data.rows()));
}

void residual_pass(benchmark::State& state, ModelKind kind, const model::PressureLaw<double>& law,
                   int threads, bool packets = true) {
  Setup s = make_setup(kind, law, threads);
  s.problem.settings = &s.settings;
  s.problem.rows.data = &s.data;
  allow_row_packets(packets);
  for (auto _ : state) benchmark::DoNotOptimize(problem_cost(s.problem, s.x));
  allow_row_packets(true);
  state.SetItemsProcessed(state.iterations() * static_cast<long>(s.data.rows()));
}

const auto kHertz = model::PressureLaw<double>::hertz();
const auto kPower17 = model::PressureLaw<double>::power(1.7);

BENCHMARK_CAPTURE(normal_equations_pass, SeedJacobianPass, ModelKind::Seed, kHertz, 1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(normal_equations_pass, SeedJacobianPass2Threads, ModelKind::Seed, kHertz, 2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(residual_pass, SeedResidualPass, ModelKind::Seed, kHertz, 1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(normal_equations_pass, SeedJacobianPassRowByRow, ModelKind::Seed, kHertz, 1,
                  false)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(residual_pass, SeedResidualPassRowByRow, ModelKind::Seed, kHertz, 1, false)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(normal_equations_pass, ExactHertzJacobianPass, ModelKind::Exact, kHertz, 1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(residual_pass, ExactHertzResidualPass, ModelKind::Exact, kHertz, 1)
    ->Unit(benchmark::kMillisecond);
// Free exponent n: each pass tabulates the ring integrals at its n (with n-slopes for the
// Jacobian), then evaluates every row from the table.
BENCHMARK_CAPTURE(normal_equations_pass, ExactPower17FreeNJacobianPass, ModelKind::Exact, kPower17,
                  1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(residual_pass, ExactPower17FreeNResidualPass, ModelKind::Exact, kPower17, 1)
    ->Unit(benchmark::kMillisecond);

}  // namespace
