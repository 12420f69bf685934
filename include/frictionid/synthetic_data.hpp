// Synthetic datasets from any model variant: a default design of slip/spin sweeps and seeded
// Gaussian noise, reproducible across platforms (own normal generator on mt19937_64).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <frictionid/dataset.hpp>
#include <frictionid/fit_observer.hpp>
#include <frictionid/model_variant.hpp>

namespace frictionid {

struct SyntheticDesign {
  std::size_t rows = 600;
  double eps_min = 1e-2, eps_max = 1e2;                  // eps = v/(|omega| R), log-spaced sweep
  std::vector<double> loads = {2000.0, 4000.0, 6000.0};  // N [N]
  double contact_radius = 0.05;                          // R [m]
  double spin = 2.0;                                     // |omega| [rad/s]; signs alternate
  std::vector<double> slip_angles = {0.0};  // alpha [rad] of the slip direction, cycled
  bool negative_slip = true;                // every 4th row slips backwards (v_x < 0)
};

struct NoiseSpec {
  double relative = 0.0;     // standard deviation as a fraction of each value
  double absolute = 0.0;     // standard deviation in the channel's units (added in quadrature)
  bool write_sigma = false;  // store the noise sigma in sigma_* columns
};

// Rows in a fixed, interleaved order; channels T_x, T_y, M_z, M_roll all present, and M_tilt
// when the spot is not a circle or h_y is not 0 (a circle's file stays as it always was). The
// model runs on up to `threads` threads (0: every hardware thread); the dataset does not depend
// on how many. The observer (may be null) hears a spot's table build (FitStage::ContactTable) and
// the rows (FitStage::ModelRows), and may cancel them (FitError("interrupted")).
Dataset generate_dataset(ModelKind kind, const model::PressureLaw<double>& law,
                         const std::array<double, kParamCount>& params,
                         const SyntheticDesign& design, const NoiseSpec& noise, std::uint64_t seed,
                         const model::ContactSpot& contact = {}, int threads = 0,
                         FitObserver* observer = nullptr);

// Standard normal deviates, platform-independent (Marsaglia polar method on mt19937_64).
class NormalStream {
 public:
  explicit NormalStream(std::uint64_t seed);
  double next();

 private:
  std::uint64_t state_[312];
  int index_;
  bool has_spare_ = false;
  double spare_ = 0.0;
  std::uint64_t next_u64();
};

}  // namespace frictionid
