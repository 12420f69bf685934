#include "identify/row_predictions.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <frictionid/fit_error.hpp>
#include <frictionid/model/contact_spot.hpp>

#include "identify/observer_progress.hpp"

namespace frictionid::row_predictions_test {
namespace {

using Law = model::PressureLaw<double>;

// Slip in every direction, both spin signs, from pure spin to pure sliding, on two loads.
model::Kinematics row(std::size_t i) {
  const double angle = 0.37 * static_cast<double>(i);
  const double speed = std::pow(10.0, -2.0 + 4.0 * std::fmod(0.618 * static_cast<double>(i), 1.0));
  const double omega = i % 7 == 3 ? 0.0 : (i % 2 == 0 ? 2.0 : -2.0);
  return {speed * std::cos(angle),
          i % 11 == 5 ? 0.0 : speed * std::sin(angle),
          omega,
          i % 3 == 0 ? 2000.0 : 4000.0,
          0.05,
          i % 5 == 1 ? -1.0 : 1.0};
}

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(RowPredictions, EqualTheModelRowByRowBitForBitOnAnyNumberOfThreads) {
  // A rectangle with both tilts: its rows are integrated one by one (no table for 150 rows).
  std::array<double, kParamCount> p = default_parameters(Law::hertz(), 0.9, 1.15, 0.08);
  p[kHy] = 0.05;
  p[kQ] = 0.6;
  const ModelEvaluator<double> model(ModelKind::Exact, Law::hertz(), p.data(), nullptr, nullptr,
                                     model::ContactSpot::rect(0.6));
  const std::size_t rows = 150;
  for (int threads : {1, 2, 3}) {
    std::vector<model::Resultants<double>> got(rows);
    std::vector<int> stored(rows, 0);
    predict_rows(
        model, rows, row,
        [&](std::size_t i, const model::Resultants<double>& r) {
          got[i] = r;
          ++stored[i];
        },
        threads);
    for (std::size_t i = 0; i < rows; ++i) {
      ASSERT_EQ(stored[i], 1) << "threads " << threads << " row " << i;
      const model::Resultants<double> want = model(row(i));
      const double a[] = {got[i].T_x,    got[i].T_y,    got[i].M_z,
                          got[i].M_roll, got[i].M_tilt, got[i].N};
      const double b[] = {want.T_x, want.T_y, want.M_z, want.M_roll, want.M_tilt, want.N};
      for (int c = 0; c < 6; ++c)
        ASSERT_TRUE(same_bits(a[c], b[c])) << "threads " << threads << " row " << i << " value "
                                           << c << ": " << a[c] << " vs " << b[c];
    }
  }
}

TEST(RowPredictions, TheFirstFailingRowsErrorIsRethrownWhicheverThreadMeetsAnother) {
  const auto p = default_parameters(Law::hertz(), 0.9, 1.0, 0.0);
  const ModelEvaluator<double> model(ModelKind::Seed, Law::hertz(), p.data());
  // Rows 40, 900 and 1500 fail; a thread may meet 900 or 1500 before another meets 40.
  const auto failing = [](std::size_t i) {
    if (i == 40 || i == 900 || i == 1500) throw std::runtime_error("row " + std::to_string(i));
    return row(i);
  };
  for (int threads : {1, 2, 4})
    for (int attempt = 0; attempt < 5; ++attempt) {
      try {
        predict_rows(
            model, 2000, failing, [](std::size_t, const model::Resultants<double>&) {}, threads);
        FAIL() << "no error on " << threads << " threads";
      } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()), "row 40") << threads << " threads";
      }
    }
}

// Hears ModelRows and remembers from which threads; cancels after `cancel_after` questions.
class Listener : public FitObserver {
 public:
  explicit Listener(long cancel_after = -1) : cancel_after_(cancel_after) {}
  void on_progress(const FitProgress& p) override {
    EXPECT_EQ(p.stage, FitStage::ModelRows);
    done.push_back(p.done);
    total = p.total;
    same_thread = same_thread && std::this_thread::get_id() == caller;
  }
  bool cancelled() const override { return cancel_after_ >= 0 && ++asked_ > cancel_after_; }
  std::vector<long> done;
  long total = 0;
  bool same_thread = true;
  const std::thread::id caller = std::this_thread::get_id();

 private:
  long cancel_after_;
  mutable std::atomic<long> asked_{0};
};

TEST(RowPredictions, TheObserverHearsTheRowsEveryStepFromTheCallingThreadOnly) {
  const auto p = default_parameters(Law::hertz(), 0.9, 1.0, 0.0);
  const ModelEvaluator<double> model(ModelKind::Seed, Law::hertz(), p.data());
  const auto ignore = [](std::size_t, const model::Resultants<double>&) {};
  Listener one;
  predict_rows(model, 5000, row, ignore, 1, &one);
  EXPECT_EQ(one.done, (std::vector<long>{1024, 2048, 3072, 4096}));
  EXPECT_EQ(one.total, 5000);
  Listener two;
  predict_rows(model, 50000, row, ignore, 2, &two);
  EXPECT_TRUE(two.same_thread);
  for (std::size_t k = 1; k < two.done.size(); ++k)
    EXPECT_GE(two.done[k] - two.done[k - 1], kRowsStep) << k;
}

TEST(RowPredictions, AnObserverThatCancelsEndsThePassWithInterrupted) {
  const auto p = default_parameters(Law::hertz(), 0.9, 1.0, 0.0);
  const ModelEvaluator<double> model(ModelKind::Seed, Law::hertz(), p.data());
  std::atomic<std::size_t> stored{0};
  Listener stop(10);
  try {
    predict_rows(
        model, 100000, row, [&stored](std::size_t, const model::Resultants<double>&) { ++stored; },
        2, &stop);
    FAIL() << "not cancelled";
  } catch (const FitError& e) {
    EXPECT_EQ(std::string(e.what()), "interrupted");
  }
  EXPECT_LT(stored.load(), 100000u);
}

TEST(RowPredictions, NoRowsStoreNothing) {
  const auto p = default_parameters(Law::hertz(), 0.9, 1.0, 0.0);
  const ModelEvaluator<double> model(ModelKind::Seed, Law::hertz(), p.data());
  int stored = 0;
  predict_rows(
      model, 0, row, [&stored](std::size_t, const model::Resultants<double>&) { ++stored; }, 2);
  EXPECT_EQ(stored, 0);
}

}  // namespace
}  // namespace frictionid::row_predictions_test
