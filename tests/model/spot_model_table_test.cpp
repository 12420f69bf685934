// The exact model on an ellipse or a rectangle reading its integrals from a table
// (ContactSpot::table, model/spot_integral_table.hpp), and a rectangle's points by strips
// (model/spot_point_integrator.hpp), against the brute-force 2-D oracle of spot_reference.hpp.
#include <frictionid/model/contact_spot.hpp>
#include <frictionid/model/pressure_table.hpp>
#include <frictionid/model/spot_integral_table.hpp>
#include <frictionid/model/spot_model.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "model/spot_cases.hpp"
#include "model/spot_reference.hpp"

namespace spot_model_table_test {
namespace {

namespace sr = frictionid::testing::spot_ref;
namespace sc = frictionid::testing::spot_cases;
namespace fm = frictionid::model;

sr::Result production(const fm::ContactSpot& spot, const fm::PressureLaw<double>& law,
                      const sr::Params& p, double q, const sr::Motion& m) {
  const fm::Kinematics k{m.v_x, m.v_y, m.omega, m.N, m.R};
  const fm::Resultants<double> r =
      fm::spot_resultants<double>({p.f, p.kappa, p.h, p.h_y, q}, law, spot, k);
  return {r.T_x, r.T_y, r.M_z, r.M_roll, r.M_tilt, r.N, 0.0};
}

fm::ContactSpot with_table(fm::ContactSpot spot, const fm::PressureLaw<double>& law, double q) {
  spot.table = std::make_shared<const fm::SpotIntegralTable>(spot, law, q);
  return spot;
}

// 14 random spots: an ellipse and a rectangle for every law of the sweep with a closed form
// (steps included; a tabulated law's table takes seconds to build), Q log-uniform in [0.4,
// 2.5], four motions each: kappa != 1, h and h_y != 0, eps from 0.05 to 6, pure spin and pure
// sliding among them. The model reads the table, the oracle integrates.
TEST(SpotModelTable, TabulatedEllipsesAndRectanglesMatchTheOracleTo1e9) {
  sc::Uniform u(0x7ab1e5);
  std::vector<sc::LawCase> laws = sc::law_cases();
  laws.pop_back();  // the tabulated law
  sc::Worst worst{"tabulated model vs oracle, friction / (f N), (f N R)"};
  for (int i = 0; i < 2 * static_cast<int>(laws.size()); ++i) {
    const sc::LawCase& lc = laws[static_cast<std::size_t>(i / 2)];
    const double q = u.log_in(0.4, 2.5);
    const bool rect = i % 2 == 1;
    const sr::Spot ref = rect ? sc::rect(q, lc.ref) : sc::ellipse(q, lc.ref);
    const fm::ContactSpot spot =
        with_table(rect ? fm::ContactSpot::rect(q) : fm::ContactSpot::ellipse(q), lc.law, q);
    for (int j = 0; j < 4; ++j) {
      const sr::Params p = sc::random_params(u, q);
      const sr::Motion m = sc::random_motion(u, 4 * i + j, 9);
      SCOPED_TRACE("case " + std::to_string(i) + "." + std::to_string(j) + ": " +
                   sc::describe(ref, lc.name, p, m));
      const sr::Result want = sr::spot_reference(ref, p, m);
      const sr::Result got = production(spot, lc.law, p, q, m);
      const double e = sc::friction_error(got, want, p, m);
      worst.add(e);
      EXPECT_LT(e, 1e-9);
      EXPECT_LT(sc::moment_error(got, want, m), 1e-12);
    }
  }
}

// A table for another aspect, or another law, is not used: the model integrates, bit for bit
// as without a table.
TEST(SpotModelTable, ATableOfAnotherAspectOrLawIsIgnored) {
  const auto hertz = fm::PressureLaw<double>::hertz();
  const fm::ContactSpot plain = fm::ContactSpot::ellipse(0.7);
  fm::ContactSpot other_q = plain, other_law = plain;
  other_q.table = std::make_shared<const fm::SpotIntegralTable>(plain, hertz, 0.8);
  other_law.table = std::make_shared<const fm::SpotIntegralTable>(
      plain, fm::PressureLaw<double>::parabolic(), 0.7);
  const sr::Params p{0.8, 1.3, 0.1, -0.05};
  const sr::Motion m{0.3, -0.2, 1.1, 50.0, 0.1};
  const sr::Result a = production(plain, hertz, p, 0.7, m);
  for (const fm::ContactSpot& s : {other_q, other_law}) {
    const sr::Result b = production(s, hertz, p, 0.7, m);
    EXPECT_EQ(a.T_x, b.T_x);
    EXPECT_EQ(a.T_y, b.T_y);
    EXPECT_EQ(a.M_z, b.M_z);
  }
}

// The centre of rotation within 1e-4 of a rectangle's corner, where rays about it would need a
// fine angular rule: strips with the y-integral in closed form stay exact there.
TEST(SpotModelTable, RectanglesAreExactNextToTheirCorners) {
  sc::Uniform u(0xc0ffee);
  const std::vector<sc::LawCase> laws = sc::law_cases();
  sc::Worst worst{"rectangle next to a corner vs oracle, friction / (f N), (f N R)"};
  for (int i = 0; i < 24; ++i) {
    const sc::LawCase& lc = laws[static_cast<std::size_t>(i) % laws.size()];
    const double q = u.log_in(0.3, 3.0);
    const sr::Spot ref = sc::rect(q, lc.ref);
    const sr::Params p = sc::random_params(u, q);
    // c = (-v_y, v_x)/(omega R) at (+-1, +-q) displaced by up to 1e-4.
    sr::Motion m{0.0, 0.0, u.sign() * u.log_in(0.2, 5.0), u.in(1.0, 300.0), u.log_in(0.01, 2.0)};
    const double cx = u.sign() * (1.0 + u.in(-1e-4, 1e-4));
    const double cy = u.sign() * (q + u.in(-1e-4, 1e-4));
    m.v_x = cy * m.omega * m.R;
    m.v_y = -cx * m.omega * m.R;
    SCOPED_TRACE("case " + std::to_string(i) + ": " + sc::describe(ref, lc.name, p, m));
    const sr::Result want = sr::spot_reference(ref, p, m);
    const sr::Result got = production(fm::ContactSpot::rect(q), lc.law, p, q, m);
    const double e = sc::friction_error(got, want, p, m);
    worst.add(e);
    EXPECT_LT(e, 1e-11);
  }
}

// A sampled law: Hertz modulated by 1 + 0.3 sin(7 rho), `samples` samples, in both descriptions.
// The oracle's law is the production interpolant itself (what is under test is the integration
// over the spot), cut at every sample, with its moments by adaptive Gauss–Kronrod between every
// two samples.
struct SampledLaw {
  fm::PressureLaw<double> law;
  sr::RadialLaw ref;
};

SampledLaw modulated_hertz_table(int samples) {
  std::vector<double> rho, sig;
  for (int i = 0; i < samples; ++i) {
    const double r = i / static_cast<double>(samples - 1);
    rho.push_back(r);
    sig.push_back(std::sqrt(1.0 - r * r) * (1.0 + 0.3 * std::sin(7.0 * r)));
  }
  const auto table = std::make_shared<const fm::PressureTable>(rho, sig);
  sr::RadialLaw ref;
  ref.name = "table of " + std::to_string(samples) + " samples";
  ref.sigma0 = [table](double r, double omr) { return (*table)(r, omr); };
  ref.breaks.assign(rho.begin() + 1, rho.end() - 1);
  ref.moment = [table, rho](int k) {
    namespace rq = frictionid::testing::ref_quad;
    std::vector<std::pair<int, std::pair<double, double>>> init;
    for (std::size_t i = 0; i + 1 < rho.size(); ++i) init.push_back({0, {rho[i], rho[i + 1]}});
    const auto panel = [&](int seg, double a, double b) {
      const auto g = rq::gk21<1>(
          [&](double r) { return rq::Vec<1>{(*table)(r, 1.0 - r) * std::pow(r, k)}; }, a, b);
      return rq::Panel<1>{seg, a, b, g.value, g.err[0], g.abs[0]};
    };
    return rq::adapt<1>(panel, init, 1e-15, 100000).value[0];
  };
  return {fm::PressureLaw<double>::tabulated(table), ref};
}

// Random motions on `spots` spots of aspect in [q_lo, q_hi], ellipses and rectangles in turn,
// against the oracle: friction within 1e-9 of f N (f N R), the load's moments within 1e-12.
void expect_oracle(const SampledLaw& s, double q_lo, double q_hi, int spots, std::uint64_t seed,
                   bool rectangles) {
  sc::Uniform u(seed);
  sc::Worst worst{s.ref.name + " vs oracle, friction / (f N), (f N R)"};
  for (int i = 0; i < spots; ++i) {
    const double q = u.log_in(q_lo, q_hi);
    const bool rect = rectangles && i % 2 == 1;
    const sr::Spot ref_spot = rect ? sc::rect(q, s.ref) : sc::ellipse(q, s.ref);
    const fm::ContactSpot spot = rect ? fm::ContactSpot::rect(q) : fm::ContactSpot::ellipse(q);
    for (int j = 0; j < 3; ++j) {
      const sr::Params p = sc::random_params(u, q);
      const sr::Motion m = sc::random_motion(u, 3 * i + j, 9);
      SCOPED_TRACE("case " + std::to_string(i) + "." + std::to_string(j) + ": " +
                   sc::describe(ref_spot, s.ref.name, p, m));
      const sr::Result want = sr::spot_reference(ref_spot, p, m);
      const sr::Result got = production(spot, s.law, p, q, m);
      const double e = sc::friction_error(got, want, p, m);
      worst.add(e);
      EXPECT_LT(e, 1e-9);
      EXPECT_LT(sc::moment_error(got, want, m), 1e-12);
    }
  }
}

// A table law of 21 to 300 samples: every sample is a kink (the interpolant is C^1, a cubic
// between two samples). Ellipses take it in layers of the uniform ellipse (cut in the layers'
// size at every sample), rectangles in strips (cut in x at every sample).
class TableLawOfSamples : public ::testing::TestWithParam<int> {};

TEST_P(TableLawOfSamples, MatchesTheOracleOnEllipsesAndRectanglesTo1e9) {
  expect_oracle(modulated_hertz_table(GetParam()), 0.4, 2.5, 4, 0x7ab1e40, true);
}

// The same on elongated ellipses, where the layers' integrand has singularities close to the
// real axis (the ray from the centre meets the rim at a shallow angle).
TEST(SpotModelTable, TableLawOf200SamplesMatchesTheOracleOnElongatedEllipses) {
  expect_oracle(modulated_hertz_table(200), 0.12, 0.3, 2, 0xe110, false);
  expect_oracle(modulated_hertz_table(200), 3.0, 4.0, 2, 0xe111, false);
}

INSTANTIATE_TEST_SUITE_P(SpotModelTable, TableLawOfSamples,
                         ::testing::Values(21, 41, 65, 100, 300));

}  // namespace
}  // namespace spot_model_table_test
