// Identification on non-circular contact spots (docs/physics.md §9.7): noise-free data generated
// by the exact model on an ellipse or a rectangle is refitted to its parameters.
#include <frictionid/fitter.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <thread>
#include <vector>

#include <frictionid/fit_observer.hpp>
#include <frictionid/model/spot_integral_table.hpp>
#include <frictionid/model/spot_point_integrator.hpp>
#include <frictionid/model_variant.hpp>
#include <frictionid/synthetic_data.hpp>
#include "identify/spot_cache.hpp"
#include "support/matched_digits.hpp"

namespace frictionid::spot_fit_test {
namespace {

using Law = model::PressureLaw<double>;
using frictionid::test::matched_digits;

// A small design with lateral slip, so that the tilt across the rolling direction shows.
SyntheticDesign small_design() {
  SyntheticDesign d;
  d.rows = 96;
  d.eps_min = 0.05;
  d.eps_max = 20.0;
  d.slip_angles = {0.0, 0.6, -1.1};
  return d;
}

std::array<double, kParamCount> truth_on(const Law& law, const model::ContactSpot& spot) {
  auto p = default_parameters(law, spot, 0.85, 1.3, 0.12);
  p[kHy] = -0.2;
  return p;
}

void expect_digits(const FitResult& r, const std::array<double, kParamCount>& truth,
                   double digits) {
  for (const auto& p : r.parameters) {
    const int i = *param_index(p.name);
    EXPECT_GE(matched_digits(p.value, truth[i]), digits) << p.name << " = " << p.value;
  }
}

TEST(SpotFit, NoiseFreeEllipseDataRecoversFrictionAndBothTiltsToEightDigits) {
  const auto spot = model::ContactSpot::ellipse(0.7);
  const auto truth = truth_on(Law::hertz(), spot);
  const Dataset d =
      generate_dataset(ModelKind::Exact, Law::hertz(), truth, small_design(), NoiseSpec{}, 3, spot);
  ASSERT_TRUE(d.has_channel(Channel::M_tilt));
  const FitResult r =
      Fitter(FitSettings::defaults(ModelKind::Exact, Law::hertz(), "hertz", spot)).fit(d);
  ASSERT_TRUE(r.solver.converged);
  bool saw_h_y = false;
  for (const auto& p : r.parameters) saw_h_y |= p.name == std::string("h_y");
  EXPECT_TRUE(saw_h_y);
  expect_digits(r, truth, 8.0);
}

TEST(SpotFit, NoiseFreeRectangleDataWithAFreeAspectRecoversTheAspectToEightDigits) {
  const auto spot = model::ContactSpot::rect(0.6);
  const auto truth = truth_on(Law::parabolic(), spot);
  const Dataset d = generate_dataset(ModelKind::Exact, Law::parabolic(), truth, small_design(),
                                     NoiseSpec{}, 4, spot);
  // The aspect starts 20 % off; the local stage alone, from near the truth.
  FitSettings s = FitSettings::defaults(ModelKind::Exact, Law::parabolic(), "parabolic",
                                        model::ContactSpot::rect(0.72));
  s.params[kQ].fixed = false;
  s.global = false;
  s.start("f", 0.8).start("kappa", 1.2).start("h", 0.1).start("h_y", -0.1);
  const FitResult r = Fitter(s).fit(d);
  ASSERT_TRUE(r.solver.converged);
  auto expected = truth;
  expected[kQ] = 0.6;
  expect_digits(r, expected, 8.0);
}

TEST(SpotFit, AFitOnAnEllipseNamesItsContactWithTheAspect) {
  const auto spot = model::ContactSpot::ellipse(0.7);
  SyntheticDesign design = small_design();
  design.rows = 300;
  const Dataset d = generate_dataset(ModelKind::Exact, Law::hertz(), truth_on(Law::hertz(), spot),
                                     design, NoiseSpec{}, 7, spot);
  const FitResult r =
      Fitter(FitSettings::defaults(ModelKind::Exact, Law::hertz(), "hertz", spot)).fit(d);
  EXPECT_EQ(r.contact, "ellipse:0.7");
}

// The label names the spot as given; the aspect the data hold is the estimate of q.
TEST(SpotFit, AFreeAspectKeepsTheGivenSpotInTheContactAndTheFittedAspectInQ) {
  const auto spot = model::ContactSpot::rect(0.6);
  const Dataset d = generate_dataset(ModelKind::Exact, Law::hertz(), truth_on(Law::hertz(), spot),
                                     small_design(), NoiseSpec{}, 8, spot);
  FitSettings s = FitSettings::defaults(ModelKind::Exact, Law::hertz(), "hertz",
                                        model::ContactSpot::rect(0.72));
  s.params[kQ].fixed = false;
  s.global = false;
  const FitResult r = Fitter(s).fit(d);
  ASSERT_TRUE(r.solver.converged);
  EXPECT_EQ(r.contact, "rect:0.72");
  ASSERT_NE(r.parameter("q"), nullptr);
  EXPECT_GE(matched_digits(r.parameter("q")->value, 0.6), 6.0) << r.parameter("q")->value;
}

TEST(SpotFit, TheRowCacheHoldsEverySpinningRowAtTheStartingAspectAndNothingWhenTheExponentIsFree) {
  const auto spot = model::ContactSpot::ellipse(0.5);
  const Dataset d =
      generate_dataset(ModelKind::Exact, Law::uniform(), truth_on(Law::uniform(), spot),
                       small_design(), NoiseSpec{}, 5, spot);
  FitSettings s = FitSettings::defaults(ModelKind::Exact, Law::uniform(), "uniform", spot);
  const auto cache = spot_cache_for_rows(d, s, 2, {});
  ASSERT_TRUE(cache);
  EXPECT_EQ(cache->size(), d.rows());  // every row spins, and no two share a centre of rotation
  // A cached lookup is the integral itself.
  const model::SpotIntegrator integrate(spot, Law::uniform(), 0.5);
  const auto [cx, cy] = model::rotation_centre(d.v_x[7], d.v_y[7], d.omega[7], d.R[7]);
  ASSERT_NE(cache->find(cx, cy), nullptr);
  EXPECT_EQ(cache->find(cx, cy)->ex[0], integrate(cx, cy).ex[0]);
  // A free aspect: the cache serves the global stage, which holds q at its start.
  s.params[kQ].fixed = false;
  const auto at_start = spot_cache_for_rows(d, s, 2, {});
  ASSERT_TRUE(at_start);
  EXPECT_EQ(at_start->q(), 0.5);
  // A free exponent changes every row's integrals at every step.
  FitSettings power = FitSettings::defaults(ModelKind::Exact, Law::power(1.5), "power", spot);
  power.params[kN].fixed = false;
  EXPECT_FALSE(spot_cache_for_rows(d, power, 2, {}));
}

// The points a table of this spot needs (model_variant.hpp, spot_table_budget).
std::size_t table_points(const model::ContactSpot& spot, const Law& law, double q) {
  return model::SpotIntegralTable(spot, law, q, {}, 2).stats().points;
}

// Where the rows outnumber the points a table needs, the cache reads a table of the plane
// instead of integrating every row: the same integrals within 3e-11 of the load A0.
TEST(SpotFit, RowsOutnumberingATablesPointsAreCachedFromTheTableWithin3e11OfTheLoad) {
  const auto spot = model::ContactSpot::rect(0.7);
  SyntheticDesign design = small_design();
  design.rows = table_points(spot, Law::hertz(), 0.7) + 100;  // every row spins
  const Dataset d = generate_dataset(ModelKind::Exact, Law::hertz(), truth_on(Law::hertz(), spot),
                                     design, NoiseSpec{}, 6, spot);
  const FitSettings s = FitSettings::defaults(ModelKind::Exact, Law::hertz(), "hertz", spot);
  const auto cache = spot_cache_for_rows(d, s, 2, {});
  ASSERT_TRUE(cache);
  EXPECT_EQ(cache->size(), d.rows());
  const double A0 = model::spot_moments(spot, model::law_moments(Law::hertz()), 0.7).A0;
  const model::SpotIntegrator integrate(spot, Law::hertz(), 0.7);
  double worst = 0.0;
  for (std::size_t i = 0; i < d.rows(); i += 97) {
    const auto [cx, cy] = model::rotation_centre(d.v_x[i], d.v_y[i], d.omega[i], d.R[i]);
    const model::SpotIntegrals a = *cache->find(cx, cy), b = integrate(cx, cy);
    for (int w = 0; w < 3; ++w)
      for (double e :
           {a.ex[w] - b.ex[w], a.ey[w] - b.ey[w], a.x_ey[w] - b.x_ey[w], a.y_ex[w] - b.y_ex[w]})
        worst = std::max(worst, std::fabs(e) / A0);
  }
  EXPECT_LT(worst, 3e-11);
  EXPECT_GT(worst, 0.0);  // it is a table, not the integrator
}

// Fewer rows than the table's points (but more than kSpotTableMinRows): the build is abandoned
// before it would cost more than the rows, and every row is integrated, bit for bit what the
// row's own integrator gives. A map's table needs tens of thousands of points, more with every
// cell, so its rows are integrated up to that many.
TEST(SpotFit, RowsFewerThanATablesPointsAreIntegratedEach) {
  const auto spot = model::ContactSpot::rect(0.7);
  const std::size_t points = table_points(spot, Law::hertz(), 0.7);
  ASSERT_GT(points, kSpotTableMinRows + 200);
  SyntheticDesign design = small_design();
  design.rows = kSpotTableMinRows + 100;
  const Dataset d = generate_dataset(ModelKind::Exact, Law::hertz(), truth_on(Law::hertz(), spot),
                                     design, NoiseSpec{}, 6, spot);
  const FitSettings s = FitSettings::defaults(ModelKind::Exact, Law::hertz(), "hertz", spot);
  const auto cache = spot_cache_for_rows(d, s, 2, {});
  ASSERT_TRUE(cache);
  const model::SpotPointIntegrator integrate(spot, Law::hertz(), 0.7);
  for (std::size_t i = 0; i < d.rows(); i += 41) {
    const auto [cx, cy] = model::rotation_centre(d.v_x[i], d.v_y[i], d.omega[i], d.R[i]);
    const auto a = cache->find(cx, cy)->channels(), b = integrate(cx, cy).channels();
    for (int k = 0; k < 12; ++k) EXPECT_EQ(a[k], b[k]) << "row " << i << ", channel " << k;
  }
  // One pass over rows (eval, generate) decides the same way.
  EXPECT_FALSE(spot_for_rows(ModelKind::Exact, Law::hertz(), 0.7, 1.0, points - 1, spot).table);
  EXPECT_TRUE(spot_for_rows(ModelKind::Exact, Law::hertz(), 0.7, 1.0, points, spot).table);
}

// What a FitObserver hears of the pass over the rows, and from which thread.
class RecordingObserver : public FitObserver {
 public:
  struct Report {
    FitStage stage;
    long done, total;
    std::thread::id thread;
  };
  void on_progress(const FitProgress& p) override {
    const std::lock_guard<std::mutex> lock(mutex_);
    reports.push_back({p.stage, p.done, p.total, std::this_thread::get_id()});
  }
  std::vector<Report> reports;

 private:
  std::mutex mutex_;
};

// Hertz on rect:0.7 over `rows` rows of the small design, every one spinning.
Dataset rect_rows(std::size_t rows) {
  const auto spot = model::ContactSpot::rect(0.7);
  SyntheticDesign design = small_design();
  design.rows = rows;
  return generate_dataset(ModelKind::Exact, Law::hertz(), truth_on(Law::hertz(), spot), design,
                          NoiseSpec{}, 6, spot);
}

bool same_cache(const model::SpotIntegralCache& a, const model::SpotIntegralCache& b,
                const Dataset& d) {
  for (std::size_t i = 0; i < d.rows(); ++i) {
    const auto [cx, cy] = model::rotation_centre(d.v_x[i], d.v_y[i], d.omega[i], d.R[i]);
    if (a.find(cx, cy)->channels() != b.find(cx, cy)->channels()) return false;
  }
  return true;
}

// The pass over a fit's rows takes seconds on a rough map or an elongated table law: the observer
// hears the table's points against its budget, then the rows done, every kTablePointsStep and
// kRowsStep, and the cache is the one computed without it. On one thread the counts are exact.
TEST(SpotFit, ThePassOverTheRowsReportsTheTablesPointsThenTheRows) {
  const auto spot = model::ContactSpot::rect(0.7);
  const std::size_t points = table_points(spot, Law::hertz(), 0.7);
  ASSERT_GT(points, kTablePointsStep);
  const Dataset d = rect_rows(points + 100);  // the budget
  const FitSettings s = FitSettings::defaults(ModelKind::Exact, Law::hertz(), "hertz", spot);
  RecordingObserver seen;
  const auto cache = spot_cache_for_rows(d, s, 1, &seen);
  ASSERT_TRUE(cache);
  std::vector<long> table, rows;
  for (const auto& r : seen.reports) {
    if (r.stage == FitStage::ContactTable) {
      EXPECT_TRUE(rows.empty()) << "the table comes first";
      EXPECT_EQ(r.total, static_cast<long>(d.rows()));
      table.push_back(r.done);
    } else {
      ASSERT_EQ(r.stage, FitStage::ContactRows);
      EXPECT_EQ(r.total, static_cast<long>(d.rows()));
      rows.push_back(r.done);
    }
  }
  std::vector<long> want_table, want_rows;
  for (long n = kTablePointsStep; n <= static_cast<long>(points); n += kTablePointsStep)
    want_table.push_back(n);
  // Reported before each chunk of kChunkRows, once kRowsStep more are done.
  for (long n = kRowsStep; n < static_cast<long>(d.rows()); n += kRowsStep) want_rows.push_back(n);
  EXPECT_EQ(table, want_table);
  EXPECT_EQ(rows, want_rows);
  EXPECT_TRUE(same_cache(*cache, *spot_cache_for_rows(d, s, 1, nullptr), d));
}

// On several threads the observer still hears from the calling thread only
// (fit_observer.hpp), with counts that only grow; a table abandoned over its budget (fewer rows
// than its points) reports no more points than the budget, and then the rows.
TEST(SpotFit, ThePassOverTheRowsReportsFromTheCallingThreadOnly) {
  const auto spot = model::ContactSpot::rect(0.7);
  ASSERT_LT(3 * kSpotTableMinRows, table_points(spot, Law::hertz(), 0.7));
  const Dataset d = rect_rows(3 * kSpotTableMinRows);
  const FitSettings s = FitSettings::defaults(ModelKind::Exact, Law::hertz(), "hertz", spot);
  RecordingObserver seen;
  const auto cache = spot_cache_for_rows(d, s, 2, &seen);
  ASSERT_TRUE(cache);
  long last_points = 0, last_rows = 0;
  bool any_rows = false;
  for (const auto& r : seen.reports) {
    EXPECT_EQ(r.thread, std::this_thread::get_id());
    if (r.stage == FitStage::ContactTable) {
      EXPECT_FALSE(any_rows);
      EXPECT_GT(r.done, last_points);
      EXPECT_LE(r.done, r.total);
      last_points = r.done;
    } else {
      any_rows = true;
      EXPECT_GT(r.done, last_rows);
      EXPECT_LT(r.done, static_cast<long>(d.rows()));
      last_rows = r.done;
    }
  }
  EXPECT_TRUE(any_rows);
  EXPECT_TRUE(same_cache(*cache, *spot_cache_for_rows(d, s, 1, nullptr), d));
}

// Work whose points are not known in advance (simulate, shimmy) takes the table, or integrates
// point by point where the table would exceed its cap, instead of failing.
TEST(SpotFit, WorkWithoutARowCountTakesTheTableUnlessItWouldExceedItsCap) {
  const auto spot = model::ContactSpot::ellipse(0.6);
  const std::size_t points = table_points(spot, Law::hertz(), 0.6);
  EXPECT_TRUE(spot_with_table_if_bounded(ModelKind::Exact, Law::hertz(), 0.6, 1.0, spot).table);
  EXPECT_TRUE(
      spot_with_table_if_bounded(ModelKind::Exact, Law::hertz(), 0.6, 1.0, spot, points).table);
  EXPECT_FALSE(
      spot_with_table_if_bounded(ModelKind::Exact, Law::hertz(), 0.6, 1.0, spot, points - 1).table);
}

TEST(SpotFit, ApproximantsRefuseANonCircularSpot) {
  FitSettings s = FitSettings::defaults(ModelKind::Seed, Law::hertz(), "hertz",
                                        model::ContactSpot::ellipse(0.7));
  std::string why;
  EXPECT_FALSE(s.validate(&why));
  EXPECT_NE(why.find("--model exact"), std::string::npos) << why;
}

TEST(SpotFit, TheCircleRefusesAFreeAspect) {
  FitSettings s = FitSettings::defaults(ModelKind::Exact, Law::hertz(), "hertz");
  s.params[kQ].fixed = false;
  std::string why;
  EXPECT_FALSE(s.validate(&why));
  EXPECT_NE(why.find("q"), std::string::npos) << why;
}

}  // namespace
}  // namespace frictionid::spot_fit_test
