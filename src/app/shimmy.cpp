#include "app/shimmy.hpp"

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <iterator>
#include <mutex>
#include <utility>

#include <ceres/jet.h>
#include <fmt/format.h>

#include <frictionid/io/input_error.hpp>
#include <frictionid/io/provenance.hpp>
#include <frictionid/model/slip_direction_table.hpp>
#include <frictionid/model_variant.hpp>
#include "app/shimmy_report_model.hpp"
#include "io/json_number.hpp"

namespace frictionid::app {

namespace {

void require(bool ok, const std::string& message) {
  if (!ok) throw InputError(message);
}

void positive(double x, const char* option) {
  require(std::isfinite(x) && x > 0.0, fmt::format("{} must be a finite number > 0", option));
}

void non_negative(double x, const char* option) {
  require(std::isfinite(x) && x >= 0.0, fmt::format("{} must be a finite number >= 0", option));
}

void check(const ShimmyRequest& r) {
  positive(r.N, "--N");
  positive(r.R, "--R");
  positive(r.speed, "--speed");
  positive(r.duration, "--duration");
  positive(r.yaw_inertia, "--yaw-inertia");
  positive(r.lateral_mass, "--lateral-mass");
  non_negative(r.yaw_stiffness, "--yaw-stiffness");
  non_negative(r.yaw_damping, "--yaw-damping");
  non_negative(r.lateral_stiffness, "--lateral-stiffness");
  non_negative(r.lateral_damping, "--lateral-damping");
  require(std::isfinite(r.caster), "--caster must be a finite number [m]");
  require(std::isfinite(r.y0), "--y0 must be a finite number [m]");
  require(std::isfinite(r.psi0) && std::fabs(r.psi0) < 0.5 * M_PI,
          "--psi0 must be a finite angle with |psi0| < pi/2 [rad]");
  require(r.lateral == "elastic" || r.lateral == "rigid",
          "--lateral '" + r.lateral + "': expected elastic or rigid");
  require(r.contact_law == "friction" || r.contact_law == "nonholonomic",
          "--contact-law '" + r.contact_law + "': expected friction or nonholonomic");
  require(r.integrator == "switching" || r.integrator == "explicit",
          "--integrator '" + r.integrator + "': expected switching or explicit");
  require(!(r.contact_law == "nonholonomic" && r.lateral == "rigid" && r.caster == 0.0),
          "--contact-law nonholonomic with --lateral rigid needs --caster != 0 (psi' = -V sin "
          "psi / e)");
  non_negative(r.output_step, "--output-step");
  require(r.output_step == 0.0 || r.duration / r.output_step <= 1e8,
          "--output-step gives more than 1e8 rows over --duration");
  require(r.tol >= 1e-14 && r.tol <= 1e-3, "--tol must be in [1e-14, 1e-3]");
  require(r.stick_threshold >= 1e-12 && r.stick_threshold <= 1e-2,
          "--stick-threshold must be in [1e-12, 1e-2]");
  require(r.cycle_tol > 0.0 && r.cycle_tol <= 0.5, "--cycle-tol must be in (0, 0.5]");
  require(r.table_directions == 0 || (r.table_directions >= 64 && r.table_directions <= 1 << 20),
          "--table-directions must be 0 (the model itself) or from 64 to 1048576");
}

}  // namespace

// The friction of one model, spot, law and parameter set, with its derivative along the
// kinematics by forward-mode automatic differentiation: the same evaluator instantiated with a
// one-direction dual number (docs/physics.md §10.8).
struct ShimmyCase::Friction {
  using Dual = ceres::Jet<double, 1>;
  struct Model {
    ModelEvaluator<double> eval;
    ModelEvaluator<Dual> dual;
    model::Resultants<double> operator()(const model::Kinematics& k) const { return eval(k); }
    model::ContactForces slip_slope(const model::Kinematics& k, const model::Kinematics& dk) const {
      const model::Resultants<Dual> r = dual(model::kinematics_along<Dual>(k, dk));
      return {r.T_x.v[0], r.T_y.v[0], r.M_z.v[0]};
    }
  };
  Friction(ModelEvaluator<double> e, ModelEvaluator<Dual> d) : model{std::move(e), std::move(d)} {}
  Model model;
  std::unique_ptr<model::SlipDirectionTable<Model>> table;
};

namespace {

// The exact model's integrals tabulated, as the friction's derivatives need (they differentiate
// the table's interpolant) and as a run's 1e4-1e6 evaluations want (0.1-0.5 us each instead of
// 3-500 us): the ring integrals of the circle, any law (the ring law's too), or the spot's table.
struct ShimmyTables {
  std::shared_ptr<const model::RingIntegralTable> ring;
  model::ContactSpot spot;
};

ShimmyTables shimmy_tables(const ModelSetup& s, const TableProgress& progress) {
  if (s.kind != ModelKind::Exact) return {nullptr, s.contact};
  if (s.contact.kind != model::SpotKind::Circle) {
    std::atomic<std::size_t> points{0};
    std::mutex one_at_a_time;
    std::function<bool()> count;
    if (progress)
      count = [&] {
        const std::size_t n = ++points;
        if (n % static_cast<std::size_t>(kTablePointsStep) == 0) {
          const std::lock_guard<std::mutex> lock(one_at_a_time);
          progress(n);
        }
        return false;
      };
    return {nullptr,
            spot_with_table_if_bounded(s.kind, s.law, s.params[kQ], s.params[kN], s.contact,
                                       model::SpotIntegralTable::kMaxPoints, count)};
  }
  // ring_table_for leaves the ring law out (its values are kernels, as cheap as a table); its
  // derivatives need the table all the same.
  if (s.law.kind == model::PressureKind::Ring)
    return {std::make_shared<const model::RingIntegralTable>(s.law), s.contact};
  return {ring_table_for(s.kind, s.law, s.params[kN], false, {}, s.contact), s.contact};
}

}  // namespace

ShimmyCase::ShimmyCase(const ShimmyRequest& r, const TableProgress& table_progress) {
  setup_ = make_model_setup(shimmy_model_request(r));
  check(r);
  wheel_.V = r.speed;
  wheel_.caster = r.caster;
  wheel_.J = r.yaw_inertia;
  wheel_.k_psi = r.yaw_stiffness;
  wheel_.c_psi = r.yaw_damping;
  wheel_.m_y = r.lateral_mass;
  wheel_.k_y = r.lateral_stiffness;
  wheel_.c_y = r.lateral_damping;
  wheel_.rigid_lateral = r.lateral == "rigid";
  wheel_.N = r.N;
  wheel_.R = r.R;
  settings_.duration = r.duration;
  settings_.rtol = settings_.atol = r.tol;
  settings_.output_step = r.output_step;
  settings_.record = r.trajectory || !r.output.empty();
  settings_.stick_threshold = r.stick_threshold;
  settings_.stiff_switching = r.integrator == "switching";
  settings_.cycle_tol = r.cycle_tol;
  settings_.law = r.contact_law == "nonholonomic" ? model::ShimmyContactLaw::Nonholonomic
                                                  : model::ShimmyContactLaw::Friction;
  start_.y = wheel_.rigid_lateral ? 0.0 : r.y0;
  start_.psi = r.psi0;
  table_directions_ = r.table_directions;
  const ModelSetup& s = setup_;
  const ShimmyTables tables = shimmy_tables(s, table_progress);
  std::array<Friction::Dual, kParamCount> dual_params;
  for (int i = 0; i < kParamCount; ++i)
    dual_params[static_cast<std::size_t>(i)] =
        Friction::Dual(s.params[static_cast<std::size_t>(i)]);
  friction_ = std::make_unique<Friction>(
      ModelEvaluator<double>(s.kind, s.law, s.params.data(), tables.ring, nullptr, tables.spot),
      ModelEvaluator<Friction::Dual>(s.kind, s.law, dual_params.data(), tables.ring, nullptr,
                                     tables.spot));
  // --table-directions: the friction at v_x = 0 over the slip direction, built once.
  if (r.table_directions > 0)
    friction_->table = std::make_unique<model::SlipDirectionTable<Friction::Model>>(
        friction_->model, wheel_.N, wheel_.R, r.table_directions);
}

ShimmyCase::~ShimmyCase() = default;

model::ShimmyRun ShimmyCase::run(const model::ShimmyWheel& wheel, const model::ShimmyStart& start,
                                 const model::ShimmySettings& settings,
                                 const std::function<void(const model::ShimmyRow&)>& row) const {
  if (friction_->table)
    return model::simulate_shimmy(*friction_->table, wheel, start, settings, row);
  return model::simulate_shimmy(friction_->model, wheel, start, settings, row);
}

nlohmann::ordered_json ShimmyCase::description(const model::ShimmyWheel& w) const {
  nlohmann::ordered_json j = model_json(setup_);
  j.update(nlohmann::ordered_json{
      {"contact_law",
       settings_.law == model::ShimmyContactLaw::Nonholonomic ? "nonholonomic" : "friction"},
      {"N", w.N},
      {"R", w.R},
      {"speed", w.V},
      {"caster", w.caster},
      {"yaw_inertia", w.J},
      {"yaw_stiffness", w.k_psi},
      {"yaw_damping", w.c_psi},
      {"lateral", w.rigid_lateral ? "rigid" : "elastic"},
      {"lateral_mass", w.m_y},
      {"lateral_stiffness", w.k_y},
      {"lateral_damping", w.c_y},
      {"y0", start_.y},
      {"psi0", start_.psi},
      {"duration", settings_.duration},
      {"integrator", settings_.stiff_switching ? "switching" : "explicit"},
      {"table_directions", friction_->table ? nlohmann::ordered_json(table_directions_)
                                            : nlohmann::ordered_json(nullptr)}});
  return j;
}

nlohmann::ordered_json run_json(const model::ShimmyRun& run) {
  using model::ShimmyIndex;
  const auto& x = run.final;
  nlohmann::ordered_json outcome{{"kind", model::outcome_name(run.outcome)}};
  if (run.outcome == model::ShimmyOutcome::LimitCycle ||
      run.outcome == model::ShimmyOutcome::Growing) {
    outcome["amplitude"] = json_number(run.cycle.amplitude);
    outcome["frequency"] = json_number(run.cycle.frequency);
  }
  if (run.outcome == model::ShimmyOutcome::Growing)
    outcome["growth_per_cycle"] = json_number(run.cycle.growth);
  if (run.outcome == model::ShimmyOutcome::Duration) {
    outcome["detail"] = model::duration_detail_name(run.cycle.detail);
    if (run.cycle.detail == model::DurationDetail::Decaying)
      outcome["growth_per_cycle"] = json_number(run.cycle.growth);
  }
  return nlohmann::ordered_json{
      {"t_end", run.t_end},
      {"final",
       {{"y", x[model::kSY]},
        {"y_dot", x[model::kSYDot]},
        {"psi", x[model::kSPsi]},
        {"psi_dot", x[model::kSPsiDot]},
        {"phase", run.in_stick ? "stick" : "slip"}}},
      {"outcome", outcome},
      {"energy",
       {{"initial", run.energy_initial},
        {"final", run.energy_final},
        {"damping_dissipated", x[model::kSDamping]},
        {"contact_work", x[model::kSContactWork]},
        {"friction_dissipated", x[model::kSFriction]},
        {"impulse_work", run.impulse_work},
        {"balance_error", (run.energy_final - run.energy_initial) -
                              (x[model::kSContactWork] - x[model::kSDamping])}}},
      {"first_switch", json_number(run.first_switch >= 0.0 ? run.first_switch : HUGE_VAL)},
      {"stick_phases", run.stick_phases},
      {"largest_projected_slip", run.largest_projected_slip},
      {"forced_switches", run.forced_switches},
      {"slip_starts", run.slip_starts},
      {"steps", run.steps},
      {"rejected_steps", run.rejected},
      {"implicit_steps", run.implicit_steps},
      {"stiffness_switches", run.stiffness_switches},
      {"evaluations", run.evaluations},
      {"step_limit_reached", run.step_limit}};
}

ShimmyResult shimmy(const ShimmyRequest& r, const TableProgress& table_progress) {
  const ShimmyCase c(r, table_progress);
  ShimmyResult out;
  const auto t0 = std::chrono::steady_clock::now();
  out.run = c.run(c.wheel(), c.start(), c.settings(),
                  [&out](const model::ShimmyRow& row) { out.rows.push_back(row); });
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  out.summary = c.description(c.wheel());
  out.summary.update(run_json(out.run));
  out.summary["wall_time_s"] = wall;
  return out;
}

std::string shimmy_csv(const std::vector<model::ShimmyRow>& rows) {
  std::string out = "t,y,y_dot,psi,psi_dot,u_y,T_y,M_z\n";
  for (const auto& s : rows)
    fmt::format_to(std::back_inserter(out),
                   "{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", s.t, s.y,
                   s.y_dot, s.psi, s.psi_dot, s.u_y, s.T_y, s.M_z);
  return out;
}

}  // namespace frictionid::app
