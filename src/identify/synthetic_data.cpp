#include <frictionid/synthetic_data.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "identify/observer_progress.hpp"
#include "identify/row_predictions.hpp"

namespace frictionid {

NormalStream::NormalStream(std::uint64_t seed) : index_(0) {
  std::mt19937_64 rng(seed);
  for (auto& s : state_) s = rng();
}

std::uint64_t NormalStream::next_u64() {
  if (index_ == 312) {
    // Refill from a generator seeded by the last block: keeps the stream deterministic.
    std::mt19937_64 rng(state_[311]);
    for (auto& s : state_) s = rng();
    index_ = 0;
  }
  return state_[index_++];
}

double NormalStream::next() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  double u, v, s;
  do {
    u = 2.0 * (static_cast<double>(next_u64() >> 11) * 0x1.0p-53) - 1.0;
    v = 2.0 * (static_cast<double>(next_u64() >> 11) * 0x1.0p-53) - 1.0;
    s = u * u + v * v;
  } while (s >= 1.0 || s == 0.0);
  const double f = std::sqrt(-2.0 * std::log(s) / s);
  spare_ = v * f;
  has_spare_ = true;
  return u * f;
}

namespace {

// The rows of one block as the observer's rows of the whole design.
class BlockObserver : public FitObserver {
 public:
  BlockObserver(FitObserver* whole, long rows) : whole_(whole), rows_(rows) {}
  long first = 0;  // the block's first row
  void on_progress(const FitProgress& p) override {
    FitProgress q = p;
    q.done += first;
    q.total = rows_;
    whole_->on_progress(q);
  }
  bool cancelled() const override { return whole_->cancelled(); }

 private:
  FitObserver* whole_;
  long rows_;
};

}  // namespace

Dataset generate_dataset(ModelKind kind, const model::PressureLaw<double>& law,
                         const std::array<double, kParamCount>& params,
                         const SyntheticDesign& design, const NoiseSpec& noise, std::uint64_t seed,
                         const model::ContactSpot& contact, int threads, FitObserver* observer) {
  if (design.rows == 0) throw std::invalid_argument("the design has no rows");
  if (!(design.eps_min > 0.0) || !(design.eps_max >= design.eps_min))
    throw std::invalid_argument("the eps range must satisfy 0 < eps_min <= eps_max");
  if (design.loads.empty() || design.slip_angles.empty())
    throw std::invalid_argument("the design needs at least one load and one slip angle");
  const ModelEvaluator<double> model(
      kind, law, params.data(),
      ring_table_for_rows(kind, law, params[kN], false, design.rows, contact), nullptr,
      observed_spot_for_rows(kind, law, params[kQ], params[kN], design.rows, contact, threads,
                             observer));
  const int channels =
      contact.kind != model::SpotKind::Circle || params[kHy] != 0.0 ? kChannelCount : 4;
  const std::size_t n = design.rows;
  const double log_lo = std::log(design.eps_min), log_hi = std::log(design.eps_max);
  const auto row = [&](std::size_t i) {
    // A golden-ratio sequence spreads eps evenly in log scale whatever the row count, and
    // interleaves loads, spin signs and slip angles so that any subsample sees them all.
    const double u =
        n == 1 ? 0.5 : std::fmod(0.5 + static_cast<double>(i) * 0.6180339887498949, 1.0);
    const double eps = std::exp(log_lo + u * (log_hi - log_lo));
    const double load = design.loads[i % design.loads.size()];
    const double omega = (i / design.loads.size()) % 2 == 0 ? design.spin : -design.spin;
    const double alpha = design.slip_angles[(i / 2) % design.slip_angles.size()];
    double v = eps * design.spin * design.contact_radius;
    if (design.negative_slip && i % 4 == 3) v = -v;
    return model::Kinematics{v * std::cos(alpha), v * std::sin(alpha), omega, load,
                             design.contact_radius};
  };
  NormalStream normal(seed);
  Dataset d;
  d.source = "generated";
  // A block of rows through the model on every thread, then its noise in row order: the same
  // numbers on any number of threads, and memory for one block's predictions only.
  constexpr std::size_t kBlock = 65536;
  std::vector<model::Resultants<double>> predicted(std::min(kBlock, n));
  BlockObserver block(observer, static_cast<long>(n));
  for (std::size_t first = 0; first < n; first += kBlock) {
    const std::size_t count = std::min(kBlock, n - first);
    block.first = static_cast<long>(first);
    predict_rows(
        model, count, [&row, first](std::size_t i) { return row(first + i); },
        [&predicted](std::size_t i, const model::Resultants<double>& r) { predicted[i] = r; },
        threads, observer ? &block : nullptr);
    for (std::size_t b = 0; b < count; ++b) {
      const std::size_t i = first + b;
      const model::Kinematics k = row(i);
      const model::Resultants<double>& r = predicted[b];
      d.line.push_back(i + 2);
      d.v_x.push_back(k.v_x);
      d.v_y.push_back(k.v_y);
      d.omega.push_back(k.omega);
      d.N.push_back(k.N);
      d.R.push_back(k.R);
      const double clean[kChannelCount] = {r.T_x, r.T_y, r.M_z, r.M_roll, r.M_tilt};
      for (int c = 0; c < channels; ++c) {
        const double sd = std::hypot(noise.relative * clean[c], noise.absolute);
        const double z = normal.next();
        d.value[c].push_back(clean[c] + sd * z);
        d.present[c].push_back(1);
        if (noise.write_sigma) d.sigma[c].push_back(sd > 0.0 ? sd : 1e-300);
      }
    }
  }
  return d;
}

}  // namespace frictionid
