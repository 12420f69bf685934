// The twelve spot integrals of spot_integrals.hpp tabulated once over the whole plane of the
// centre of rotation c, for one spot (an ellipse, a rectangle or a pressure map), aspect q and
// pressure law. A
// fit with those fixed evaluates the same twelve functions of c at every row of every iteration
// (docs/physics.md §9.3); the table answers in ~0.3 us where the ray integration of
// SpotIntegrator takes 100-300 us, after a build of 0.05-0.4 s of CPU time.
//
// Symmetry. The spot is symmetric under x -> -x and y -> -y. Reflecting x turns e_y and the
// weight x, reflecting y turns e_x and the weight y, so each integral is even or odd in each of
// c_x and c_y (kOddX, kOddY) and only the quadrant c_x, c_y >= 0 is tabulated.
//
// Where the integrals are not smooth. They are a convolution of the weighted pressure with the
// direction field e3 x d/|d|, hence analytic in c except on the lines where sigma0 is not: the
// ellipse's rim and step circles, the rectangle's sides and steps |x| = B, and its edges y = +-q
// (sigma0 is uniform across y, so it jumps there for every law). Across such a line the
// integrals go like d^2 ln|d| (a jump of sigma0), d^(n+2) (sigma0 ~ d^n at a rim) or d ln|d|
// (the ring law); where two lines meet (the rectangle's corners, a step meeting the edge) the
// singularity is a point.
//
// Patches. The quadrant is covered by patches whose coordinate lines follow those sets:
//  - ellipse: reference polar coordinates (P, beta) of (c_x, c_y/q) for P <= P_near: the rim and
//    every step are circles P = const. Below aspect 0.3 only inside the rim, and outside it
//    confocal coordinates (mu, nu) about the foci (+-sqrt(1 - q^2), 0), out to the confocal
//    ellipse of minor semi-axis R_near: the rim is mu = atanh(q), and they are conformal, so a
//    cell square in them is square on the plane. The polar cells along the long sides were 1/q
//    times longer along the rim than across it (144,000 points at q = 0.02, now 6,300);
//  - rectangle: physical Cartesian coordinates in the box [0, R_near]^2, and a disk of polar
//    coordinates (rho, theta) about every corner (x_s, q) (x_s = 1 or a step B), in which the
//    lines through the corner are rays theta = const; the box's cells next to a corner lie
//    inside its disk. Physical, not reference, coordinates: there the direction field is
//    isotropic and the distance to a line measures how far the integrals stay analytic;
//  - far: t = 1/|c| in [0, 1/R_near] and the physical angle gamma. t = 0 is the sliding limit
//    e = (sin gamma, -cos gamma), from the moments A0, Axx, Ayy; R_near is 1.5 times the spot's
//    largest radius, which bounds the expansion in t (radius 1/max|r|).
//  - map: no symmetry, so the whole plane: a Cartesian box about the map's centre holding the
//    disk of radius R_near (1.5 times its half-diagonal), every grid line a cell boundary, each
//    interval between two lines one root cell and one cell from each edge out; the far patch
//    about the map's centre over the full turn, with the map's own moments (Ax, Ay, Axy need
//    not vanish). Its points come from MapStripIntegrator (map_strip_integrator.hpp). The
//    integrals go like d^3 ln d across every grid line and d^2 ln d across the edges, but on a
//    root cell only the grid cells that touch it are not smooth: each root cell holds the
//    integrals less theirs and those of the ring of grid cells about them (its near cells, up to
//    5 x 5), which a reading adds back by their corner sums (map_corner_sums.hpp, 0.6-0.9 us),
//    so that what it holds is analytic on it, two grid cells from its nearest singular line, and
//    its cells need no grading.
// Each patch is a grid of root cells. On both sides of every singular line (and about every
// corner) a cell of width 0.35 is graded as u = u_s +- w ((1 -+ s)/2)^3 in its coordinate
// s in [-1, 1] (powers 4 and 6 for the ring law's d ln d): d^2 ln d becomes s^6 ln s, which a
// Chebyshev series of degree 24-48 resolves to 1e-11. The reference angle of an elongated
// ellipse is graded towards both axes at the scale atanh(min(q, 1/q)), the distance of its
// branch points from the real line.
//
// Build. Every root cell is sampled on Chebyshev extreme points, first of degree 8 each way,
// then of the degree (a multiple of the last, so that the points nest and none is computed
// twice) at which its coefficients, extrapolated at the rate of their upper half, fall below
// kSampleTolerance; the error estimate sums that geometric tail. A cell that needs more than
// degree 64 is halved. One more point per cell checks the interpolant. Points shared by
// neighbouring cells are computed once, each round's points in parallel. The sampling degree is
// thus set by what the function needs, not by the cost of an evaluation: the accepted series are
// then cut, without new samples, into pieces of degree <= 16 each way (the series re-expanded
// exactly on halves until what a cut drops sums to < kStoreTolerance), and each piece keeps per
// row only the coefficients that matter. The build is deterministic: the same bits on any number
// of threads. 2,000-8,000 points for an ellipse, 8,000-23,000 for a rectangle at q = 0.4-2.5;
// an ellipse of aspect 0.001-0.3 5,000-12,000 (the ring law up to 30,000), of aspect 4 11,000;
// a map ~100 per grid cell (degree 10 each way) and ~400 per outside cell (36 away from the edge):
// 22,000 for the 13 x 9 footprint, 42,000 for a rough random 15 x 15 grid (66,000 and 192,000
// with the cells graded, before the near cells were held apart; 29,000 and 63,000 with only the
// touching cells held apart).
//
// The points. Ellipse: SpotIntegrator, whose rays are closed forms under the power laws (uniform,
// Hertz, parabolic, power:n: 6-20 us a point); under a table law, layers of the uniform ellipse
// (ellipse_law_integrator.hpp) from that ellipse's own table, built first (below 64 samples by
// the rays' stretches through its pieces, whose weights the points that share a reference radius
// share: Ray::stretches; from 64 a product rule whose readings do not grow with them; either way
// the points that share an angle share each piece's sums at it, AngleRows; the table
// takes 9,000-49,000 points, every sample a line its cells resolve, below 64 samples a boundary of
// them). An annulus has no
// points of its own: it is the uniform ellipse less the one scaled by its inner radius, two
// readings of the uniform table (built to a tolerance tightened by (1 - B^2)/(1 + B^2), the
// annulus' load over what the two carry). Rectangle: RectStripIntegrator
// (rect_strip_integrator.hpp), the y-integral in closed form: 10-30 us a point (a table law of
// 201-1001 samples: 10-41 us by the product rule), and exact next to the corners, where
// SpotIntegrator's default angular rule errs by up to 5e-9 A0.
//
// Accuracy: within 3e-11 A0 of the integrals (|ex|, |ey| <= A0) over the whole plane for the
// uniform, Hertz, parabolic and annulus laws and q from 0.4 to 2.5, measured at 4,000 random
// centres including the spot's centre, the rim and edges to 1e-8, the corners, and |c| up to
// 1e6 (tests/model/spot_integral_table_test.cpp); stats().estimate is the build's own worst
// estimate. Maps: within 2e-11 A0 of MapStripIntegrator for the footprint, 3e-11 for a rough
// random 15 x 15 grid (the check points accept 5e-11). Cost: experiments/README.md, "Contact
// spots".
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

#include <frictionid/model/chebyshev_values.hpp>
#include <frictionid/model/contact_spot.hpp>
#include <frictionid/model/ellipse_law_integrator.hpp>
#include <frictionid/model/gauss_legendre_rule.hpp>
#include <frictionid/model/map_strip_integrator.hpp>
#include <frictionid/model/plane_dual.hpp>
#include <frictionid/model/pressure_law.hpp>
#include <frictionid/model/rect_strip_integrator.hpp>
#include <frictionid/model/scalar_ops.hpp>
#include <frictionid/model/shared_memo.hpp>
#include <frictionid/model/spot_integrals.hpp>
#include <frictionid/model/tanh_sinh_rule.hpp>

namespace frictionid::model {

// Thrown by a table build that its `stop` check asked to stop (a cancelled fit).
class SpotTableBuildStopped : public std::runtime_error {
 public:
  SpotTableBuildStopped() : std::runtime_error("the spot-integral table's build was stopped") {}
};

// Thrown by a table build before it would compute more points than its budget allows: its
// caller integrates instead (model_variant.hpp, spot_table_budget).
class SpotTableOverBudget : public std::runtime_error {
 public:
  SpotTableOverBudget() : std::runtime_error("the spot-integral table would exceed its budget") {}
};

// Calls work(i) for every i in [0, count), on any number of threads, and returns when all calls
// have finished. A fit passes its own thread pool.
using SpotParallelFor =
    std::function<void(std::size_t count, const std::function<void(std::size_t)>& work)>;

// A SpotParallelFor on `threads` threads (0: every hardware thread), the caller's among them. An
// exception thrown by work is rethrown after every thread has finished.
inline SpotParallelFor spot_threads(int threads) {
  return [threads](std::size_t count, const std::function<void(std::size_t)>& work) {
    unsigned n = threads > 0 ? static_cast<unsigned>(threads) : std::thread::hardware_concurrency();
    n = static_cast<unsigned>(
        std::min<std::size_t>(std::max(1u, n), std::max<std::size_t>(1, count)));
    std::atomic<std::size_t> next{0};
    std::exception_ptr error;
    std::mutex error_mutex;
    auto run = [&] {
      for (std::size_t i; (i = next.fetch_add(1, std::memory_order_relaxed)) < count;) {
        try {
          work(i);
        } catch (...) {
          const std::lock_guard<std::mutex> lock(error_mutex);
          if (!error) error = std::current_exception();
          next = count;
        }
      }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < n; ++t) pool.emplace_back(run);
    run();
    for (auto& t : pool) t.join();
    if (error) std::rethrow_exception(error);
  };
}

class SpotIntegralTable {
 public:
  static constexpr int kChannels = 12;  // ex[0..2], ey[0..2], x_ey[0..2], y_ex[0..2]

  // Tabulates the integrals of an ellipse or a rectangle (a circle is the ellipse q = 1) with
  // aspect q and this law, or of a pressure map (q and the law are ignored; the table keeps the
  // map). A spot without load throws std::invalid_argument. The build asks `stop` before every
  // point, from the worker threads, and throws SpotTableBuildStopped when it says so. It
  // computes at most `max_points` points (stats().points; a table law's points, not those of
  // the uniform ellipse's table they come from) and throws SpotTableOverBudget, before computing
  // them, when a round would take it beyond: a table whose points are noisy (rounding in the
  // integrals it samples) would otherwise halve its cells to kMaxDepth.
  static constexpr std::size_t kMaxPoints = 2000000;  // ~300 MB of points during the build

  SpotIntegralTable(const ContactSpot& spot, const PressureLaw<double>& law, double q,
                    const std::function<bool()>& stop = {}, int threads = 0,
                    std::size_t max_points = kMaxPoints)
      : SpotIntegralTable(spot, law, q, stop, spot_threads(threads), max_points) {}

  SpotIntegralTable(const ContactSpot& spot, const PressureLaw<double>& law, double q,
                    const std::function<bool()>& stop, const SpotParallelFor& parallel,
                    std::size_t max_points = kMaxPoints)
      : SpotIntegralTable(spot, law, q, stop, parallel, 1.0, max_points) {}

  // The unit uniform ellipse of aspect q as a table law's table reads it for its points
  // (EllipseLawIntegrator: along rays c/s, ~500 readings a point). Down to aspect kPolarLayers
  // its polar patch reaches beyond the rim as it does for q >= kConfocal, where the confocal
  // patch would make every reading there a full 2-D series (the confocal angle changes along a
  // ray): at q = 0.1 it takes 31,000 points where the confocal one takes 5,400, and a table law
  // of 41 samples then builds 1.6 times faster (1.6 at q = 0.05, 1.75 at 0.2), with the same
  // points. Rows integrated one by one (SpotPointIntegrator) keep the confocal table, which is
  // cheaper to build than the readings it saves on a few thousand rows. Below kConfocal its
  // points are readings of a confocal table built first to a tolerance kSourceTighter times its
  // own (0.3 us a point where the rays take ~15 us; the 31,000 points at q = 0.1 took 0.7 s,
  // now 0.5 s with the confocal table's 0.15 s, the same points and the same error against the
  // rays).
  static std::shared_ptr<const SpotIntegralTable> uniform_for_layers(
      double q, const std::function<bool()>& stop, const SpotParallelFor& parallel) {
    return std::shared_ptr<const SpotIntegralTable>(
        new SpotIntegralTable(ContactSpot::ellipse(q), PressureLaw<double>::uniform(), q, stop,
                              parallel, 1.0, kMaxPoints, q >= kPolarLayers));
  }

 private:
  // The same with every tolerance `tighter` times its own (a table that others take
  // differences of), and, `polar`, no confocal patch (uniform_for_layers).
  SpotIntegralTable(const ContactSpot& spot, const PressureLaw<double>& law, double q,
                    const std::function<bool()>& stop, const SpotParallelFor& parallel,
                    double tighter, std::size_t max_points, bool polar = false)
      : polar_(polar),
        kind_(spot.kind == SpotKind::Map    ? SpotKind::Map
              : spot.kind == SpotKind::Rect ? SpotKind::Rect
                                            : SpotKind::Ellipse),
        law_(law),
        q_(spot.has_aspect() ? q : 1.0),
        map_(kind_ == SpotKind::Map ? spot.map : nullptr) {
    if (kind_ == SpotKind::Map && !map_) throw std::invalid_argument("a map spot without its map");
    if (!(q_ > 0.0) || !std::isfinite(q_))
      throw std::invalid_argument("the spot's aspect q must be > 0");
    const SpotMoments<double> m = spot_moments(spot, law_moments(law), q_);
    if (!(m.A0 > 0.0)) throw std::invalid_argument("the spot carries no load");
    A0_ = m.A0;
    scale_ = tighter * m.A0;
    Ax_ = m.Ax;
    Ay_ = m.Ay;
    Axx_ = m.Axx;
    Axy_ = m.Axy;
    Ayy_ = m.Ayy;
    // An annulus on an ellipse is the uniform ellipse less the one scaled by B (physics.md
    // (9.8)): U(c) - B^(2+d) U(c/B), two readings of the uniform ellipse's table, where a table
    // of its own resolves the step's ellipse (4x the points at q = 0.1).
    if (kind_ == SpotKind::Ellipse && law.kind == PressureKind::Annulus) {
      const double B = law.inner_radius();
      // Its error, e(c) + B^(2+d) e(c/B), is held to the annulus' own load (1 - B^2) A0.
      uniform_.reset(new SpotIntegralTable(ContactSpot::ellipse(q_), PressureLaw<double>::uniform(),
                                           q_, stop, parallel, (1.0 - B * B) / (1.0 + B * B),
                                           max_points));
      inner_ = B;
      inner_weight_ = SpotIntegrals::scale_weights(B);
      stats_ = uniform_->stats();
      stats_.layer_points = stats_.points;
      return;
    }
    // The laws that reach the rays here: on an ellipse the power laws (uniform, Hertz,
    // parabolic, power:n), whose rays are closed forms, and the ring, integrated along the rim;
    // on a rectangle only the ring (the others by strips). An annulus on an ellipse comes from
    // the uniform ellipse's table and a table law from layers of it (below).
    const SpotIntegrator integrate(spot, law, q_);
    // (The strips only on a rectangle: under a table law they compute its weights up front.)
    const RectStripIntegrator strips(kind_ == SpotKind::Rect ? law : PressureLaw<double>::uniform(),
                                     q_);
    const PressureMap none;
    const MapStripIntegrator map_strips(map_ ? *map_ : none);
    // A table law on an ellipse: its points from the uniform ellipse's table, layer by layer.
    std::optional<EllipseLawIntegrator<SpotIntegralTable>> layers;
    if (kind_ == SpotKind::Ellipse && law.kind == PressureKind::Table) {
      auto uniform = uniform_for_layers(q_, stop, parallel);
      stats_.layer_points = uniform->stats().points;
      layers.emplace(std::move(uniform), law, q_, false, true);
    }
    // The layers' polar table of an elongated ellipse: its points from the confocal one.
    std::unique_ptr<SpotIntegralTable> confocal;
    if (polar_ && kind_ == SpotKind::Ellipse && law.kind == PressureKind::Uniform && q_ < kConfocal)
      confocal.reset(new SpotIntegralTable(spot, law, q_, stop, parallel, tighter * kSourceTighter,
                                           max_points, false));
    Builder{*this,          integrate, strips,   map_strips, layers ? &*layers : nullptr,
            confocal.get(), stop,      parallel, max_points, {}}
        .run();
  }

 public:
  // The integrals for the centre of rotation at physical (cx, cy), units of R.
  SpotIntegrals operator()(double cx, double cy) const {
    return SpotIntegrals::from_channels(channels_at(cx, cy).data());
  }

  // The same as twelve channels (SpotIntegrals::channels()); cx and cy may be dual numbers, and
  // the channels then carry the interpolant's derivatives along them.
  template <typename E>
  std::array<E, kChannels> channels_at(const E& cx, const E& cy) const {
    if (uniform_) {  // an annulus: U(c) - B^(2+d) U(c/B)
      std::array<E, kChannels> v = uniform_->channels_at(cx, cy);
      const std::array<E, kChannels> in = uniform_->channels_at(E(cx / inner_), E(cy / inner_));
      for (int j = 0; j < kChannels; ++j) v[j] -= inner_weight_[j] * in[j];
      return v;
    }
    std::array<E, kChannels> v;
    if (kind_ == SpotKind::Map) {
      evaluate(cx, cy, v.data());  // a map has no symmetry: the whole plane is tabulated
    } else {
      evaluate(magnitude(cx), magnitude(cy), v.data());
      const bool fx = std::signbit(value_of(cx)), fy = std::signbit(value_of(cy));
      for (int j = 0; j < kChannels; ++j)
        if ((fx && kOddX[j]) != (fy && kOddY[j])) v[j] = -v[j];
    }
    return v;
  }

 private:
  // One coordinate of a root cell: s in [-1, 1] to the patch coordinate u in [lo, hi], linear or
  // graded towards a singular line at hi, u = hi - (hi - lo) ((1 - s)/2)^power (at lo: mirrored).
  struct Axis {
    double lo = 0.0, hi = 1.0;
    int power = 1;  // 1: linear
    bool towards_hi = true;

    double at(double s) const {
      if (s == -1.0) return lo;
      if (s == 1.0) return hi;
      if (power == 1) return lo + (hi - lo) * 0.5 * (s + 1.0);
      if (towards_hi) return hi - (hi - lo) * std::pow(0.5 * (1.0 - s), power);
      return lo + (hi - lo) * std::pow(0.5 * (1.0 + s), power);
    }
    double slope(double s) const {  // du/ds
      if (power == 1) return 0.5 * (hi - lo);
      const double a = 0.5 * (towards_hi ? 1.0 - s : 1.0 + s);
      double p = 1.0;
      for (int k = 1; k < power; ++k) p *= a;
      return 0.5 * power * (hi - lo) * p;
    }
    template <typename E>
    E s_of(const E& u) const {
      if (power == 1) return std::clamp(E(2.0 * (u - lo) / (hi - lo) - 1.0), E(-1.0), E(1.0));
      if (towards_hi) return 1.0 - 2.0 * root(std::clamp(E((hi - u) / (hi - lo)), E(0.0), E(1.0)));
      return 2.0 * root(std::clamp(E((u - lo) / (hi - lo)), E(0.0), E(1.0))) - 1.0;
    }
    template <typename E>
    E root(const E& x) const {
      using std::cbrt;
      using std::pow;
      using std::sqrt;
      if (power == 3) return cbrt(x);
      if (power == 4) return sqrt(sqrt(x));
      if (power == 6) return sqrt(cbrt(x));
      return pow(x, 1.0 / power);
    }
  };

 public:
  // The pieces of this table summed over their angular rows at one angular coordinate, for the
  // rays of a table law's build (Ray::add_to, EllipseLawIntegrator): every point of an angular
  // column of the build's cells reads this table along rays at the same angle, so each piece it
  // passes is summed at that angle once, and a ray's weights then meet a radial series, n1 + 1
  // times fewer products (sum_piece at every point took a tenth of a build). A piece's sums
  // depend only on the piece and the angular coordinate, bit for bit, so the build does not
  // depend on which point found them first. Shared by the threads.
  struct AngleKey {
    int leaf;
    double s1;
    bool operator==(const AngleKey& o) const { return leaf == o.leaf && s1 == o.s1; }
  };
  struct AngleKeyHash {
    std::size_t operator()(const AngleKey& k) const {
      const double s1 = k.s1 + 0.0;  // -0 and +0 compare equal: one hash
      std::uint64_t b;
      std::memcpy(&b, &s1, sizeof b);
      std::uint64_t z = b ^ (static_cast<std::uint64_t>(k.leaf) * 0x9e3779b97f4a7c15ULL);
      z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
      z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
      return static_cast<std::size_t>(z ^ (z >> 31));
    }
  };
  // Cleared beyond 15,000 (~30 MB at 17 x 12 coefficients each).
  using AngleRows =
      SharedMemo<AngleKey, std::shared_ptr<const std::vector<double>>, AngleKeyHash, 15000>;

  // Readings along the ray c/s, s > 0, from one centre c: a table law's layers read the uniform
  // ellipse at c/s for 250-650 values of s (ellipse_law_integrator.hpp). On an ellipse's table
  // the angular coordinate of both patches (the reference angle of the polar patch, the
  // physical angle of the far one) is the same for every s, so a layer's reading only adds its
  // weights to its piece's radial Chebyshev sums (add), and each piece is summed against them
  // once (add_to). A single reading, operator(), gives the same values as
  // channels_at(c_x/s, c_y/s) but for rounding. Other tables read channels_at.
  class Ray {
   public:
    std::array<double, kChannels> operator()(double s) const {
      std::array<double, kChannels> v{};
      double s0 = 0.0, s1 = 0.0;
      int index = -1;
      if (!find(s, s0, s1, index)) return t_->channels_at(cx_ / s, cy_ / s);
      if (index < 0) return v;  // not on an ellipse's patches
      const Leaf& leaf = t_->leaves_[static_cast<std::size_t>(index)];
      double tx[kStoreDegree + 1];
      chebyshev_values(leaf_coordinate(leaf.a0, leaf.b0, s0), leaf.n0, tx);
      sum_piece(index, s1, tx, tx, tx, v.data());
      for (int j = 0; j < kChannels; ++j)
        if ((fx_ && kOddX[j]) != (fy_ && kOddY[j])) v[j] = -v[j];
      return v;
    }

    // Adds w s^(2+d) U(c/s) to the ray's sums, d each channel's degree
    // (SpotIntegrals::kChannelDegree: a layer of physics.md (9.8)); add_to then adds the sums to
    // twelve channels. A reading adds its three weights times T_k(x) to its piece's Chebyshev
    // weights, 3 (n0 + 1) products where operator() and the layer take 24 (n0 + 1), and each
    // piece's coefficients are summed against them once, in add_to: the twelve-channel series
    // at every reading took a third of a table law's build.
    void add(double s, double w) const {
      const double w2 = w * s * s, w3 = w2 * s, w4 = w3 * s;
      double s0 = 0.0, s1 = 0.0;
      int index = -1;
      if (!find(s, s0, s1, index)) {
        const std::array<double, kChannels> u = t_->channels_at(cx_ / s, cy_ / s);
        for (int j = 0; j < kChannels; ++j)
          direct_[j] += (SpotIntegrals::kChannelDegree[j] == 0   ? w2
                         : SpotIntegrals::kChannelDegree[j] == 1 ? w3
                                                                 : w4) *
                        u[j];
        return;
      }
      if (index < 0) return;
      const Leaf& leaf = t_->leaves_[static_cast<std::size_t>(index)];
      double* W = weights(index, s1);
      double tx[kStoreDegree + 1];
      chebyshev_values(leaf_coordinate(leaf.a0, leaf.b0, s0), leaf.n0, tx);
      for (int k = 0; k <= leaf.n0; ++k) {
        W[k] += w2 * tx[k];
        W[kWeightRow + k] += w3 * tx[k];
        W[2 * kWeightRow + k] += w4 * tx[k];
      }
    }

    // The ray by stretches (a table law's build, EllipseLawIntegrator): the part of the ray c/s,
    // s in (0, 1], that one piece holds. There U is a Chebyshev series in the piece's radial
    // coordinate x whose coefficients depend on the angle alone, and the radial coordinate u of
    // the patch is P/s on the polar patch (P the reference radius of c) and s/|c| on the far
    // one: so the weights of a layer integral over the stretch, W_k = ∫ w(s) s^(2+d) T_k(x) ds,
    // depend on the ray only through P or |c|, not its angle.
    struct Stretch {
      int leaf;
      double s1;          // the angular coordinate in the piece's root cell
      bool far;           // on the far patch: u = s/|c|, else u = P/s
      Axis axis;          // the root cell's radial coordinate
      double a0, b0;      // the piece's side in it
      double u_lo, u_hi;  // the stretch, in u
      // u at the piece's coordinate x in [-1, 1], and du/dx.
      double u_at(double x, double& du_dx) const {
        const double h = 0.5 * (b0 - a0), sigma = a0 + h * (x + 1.0);
        du_dx = axis.slope(sigma) * h;
        return axis.at(sigma);
      }
      double x_of(double u) const { return leaf_coordinate(a0, b0, axis.s_of(u)); }
    };

    // The stretches of the ray over s in (0, 1] in order of increasing u, or false where the
    // ray is not read by pieces (a map or rectangle, the confocal patch, c = 0).
    bool stretches(std::vector<Stretch>& out) const {
      out.clear();
      if (!t_->ray_by_slices() || centre_ || t_->confocal_) return false;
      // The polar patch for u = P/s in [P, P_near], the far one for s < P/P_near.
      if (P_ <= t_->near_) along(0, P_, t_->near_, out);
      if (r_ < HUGE_VAL) along(1, 0.0, std::min(1.0, P_ / t_->near_) / r_, out);
      return true;
    }
    double reference_radius() const { return P_; }
    double radius() const { return r_; }

    // Adds the weights W (three rows of kWeightRow, as add() sums them) to piece `leaf` at s1.
    void add_weights(int leaf, double s1, const double* W) const {
      double* to = weights(leaf, s1);
      for (int k = 0; k < 3 * kWeightRow; ++k) to[k] += W[k];
    }

    void add_to(double* acc) const {
      double out[kChannels] = {};
      for (const Visit& v : visits_) {
        const double* W = weights_.data() + v.offset;
        sum_piece(v.leaf, v.s1, W, W + kWeightRow, W + 2 * kWeightRow, out);
      }
      finish(out, acc);
    }

    // The same, each piece's coefficients first summed over its angular rows at the ray's
    // angle and kept in `rows` (AngleRows), where later rays at that angle find them.
    void add_to(double* acc, AngleRows& rows) const {
      thread_local std::vector<AngleKey> keys;
      thread_local std::vector<std::shared_ptr<const std::vector<double>>> found;
      const std::size_t n = visits_.size();
      keys.resize(n);
      for (std::size_t i = 0; i < n; ++i) keys[i] = {visits_[i].leaf, visits_[i].s1};
      rows.get(keys, found, [&](std::size_t i) {
        return std::make_shared<const std::vector<double>>(
            reduce_piece(visits_[i].leaf, visits_[i].s1));
      });
      double out[kChannels] = {};
      for (std::size_t i = 0; i < n; ++i) {
        const double* W = weights_.data() + visits_[i].offset;
        const std::vector<double>& a = *found[i];
        const std::size_t len = a.size() / kChannels;
        for (std::size_t k = 0; k < len; ++k) {
          const double w[3] = {W[k], W[kWeightRow + k], W[2 * kWeightRow + k]};
          for (int j = 0; j < kChannels; ++j)
            out[j] += w[SpotIntegrals::kChannelDegree[j]] * a[k * kChannels + j];
        }
      }
      finish(out, acc);
    }

   private:
    friend class SpotIntegralTable;
    Ray(const SpotIntegralTable& t, double cx, double cy) : t_(&t), cx_(cx), cy_(cy) {
      const double ax = std::fabs(cx), ay = std::fabs(cy);
      fx_ = std::signbit(cx);
      fy_ = std::signbit(cy);
      P_ = std::hypot(ax, ay / t.q_);
      r_ = std::hypot(ax, ay);
      centre_ = !(P_ > 0.0);
      u1_[0] = std::atan2(ay / t.q_, ax);
      u1_[1] = std::atan2(ay, ax);
    }

    // The piece that holds c/s by its index (-1: none, outside the ellipse's patches) and its
    // root cell's coordinates there; false where the ray is not read by pieces (channels_at).
    bool find(double s, double& s0, double& s1, int& index) const {
      if (!t_->ray_by_slices() || centre_) return false;
      const double P = P_ / s;
      // Beyond the rim of an elongated ellipse the confocal angle changes along the ray.
      if (t_->confocal_ && P > t_->near_) return false;
      const std::size_t patch = P <= t_->near_ ? 0 : 1;
      const double u0 = patch == 0 ? P : (r_ < HUGE_VAL ? s / r_ : 0.0), u1 = u1_[patch];
      const Patch& g = t_->patches_[patch];
      // The angle is the same at every reading: its cell once per patch, its cell coordinate
      // once per root cell in a row.
      if (i1_[patch] == kUnset) i1_[patch] = locate(g.breaks1, u1);
      // Consecutive readings mostly fall in the root cell and the piece of the last one: both
      // are kept, and the search and the descent (a quarter of a reading) skipped.
      if (!(patch == last_patch_ && u0 >= last_lo_ && u0 < last_hi_)) {
        const std::size_t i0 = locate(g.breaks0, u0);
        last_patch_ = patch;
        last_lo_ = g.breaks0[i0];
        last_hi_ = i0 + 2 == g.breaks0.size() ? HUGE_VAL : g.breaks0[i0 + 1];
        const int r = g.roots[i0 * (g.breaks1.size() - 1) + i1_[patch]];
        if (r != last_root_) {
          last_root_ = r;
          last_leaf_ = -1;
          if (r >= 0) last_s1_ = t_->roots_[static_cast<std::size_t>(r)].a1.s_of(u1);
        }
      }
      if (last_root_ < 0) return true;
      const Root& root = t_->roots_[static_cast<std::size_t>(last_root_)];
      s0 = root.a0.s_of(u0);
      s1 = last_s1_;
      if (last_leaf_ >= 0) {
        const Leaf& leaf = t_->leaves_[static_cast<std::size_t>(last_leaf_)];
        if (s0 >= leaf.a0 && s0 < leaf.b0) {
          index = last_leaf_;
          return true;
        }
      }
      const TreeNode* node = &t_->tree_[static_cast<std::size_t>(root.tree)];
      while (node->dir >= 0)
        node = &t_->tree_[static_cast<std::size_t>(
            node->child[(node->dir == 0 ? s0 : s1) >= node->mid])];
      index = last_leaf_ = node->leaf;
      return true;
    }

    // The stretches of patch `patch` for u in [lo, hi], at the ray's angle.
    void along(std::size_t patch, double lo, double hi, std::vector<Stretch>& out) const {
      if (!(hi > lo)) return;
      const Patch& g = t_->patches_[patch];
      const double u1 = u1_[patch];
      const std::size_t i1 = locate(g.breaks1, u1), columns = g.breaks1.size() - 1;
      for (std::size_t i0 = locate(g.breaks0, lo); i0 + 1 < g.breaks0.size(); ++i0) {
        if (g.breaks0[i0] >= hi) break;
        const int r = g.roots[i0 * columns + i1];
        if (r < 0) continue;
        const Root& root = t_->roots_[static_cast<std::size_t>(r)];
        const double s1 = root.a1.s_of(u1);
        const double ulo = std::max(lo, g.breaks0[i0]), uhi = std::min(hi, g.breaks0[i0 + 1]);
        if (!(uhi > ulo)) continue;
        collect(root.tree, root.a0, root.a0.s_of(ulo), root.a0.s_of(uhi), s1, patch == 1, ulo, uhi,
                out);
      }
    }
    // The pieces of the subtree at `node` over [x0, x1] in the root's radial coordinate, at s1.
    void collect(int node, const Axis& axis, double x0, double x1, double s1, bool far, double ulo,
                 double uhi, std::vector<Stretch>& out) const {
      const TreeNode& n = t_->tree_[static_cast<std::size_t>(node)];
      if (n.dir == 1) {
        collect(n.child[s1 >= n.mid], axis, x0, x1, s1, far, ulo, uhi, out);
      } else if (n.dir == 0) {
        if (x0 < n.mid) collect(n.child[0], axis, x0, x1, s1, far, ulo, uhi, out);
        if (x1 > n.mid) collect(n.child[1], axis, x0, x1, s1, far, ulo, uhi, out);
      } else {
        const Leaf& leaf = t_->leaves_[static_cast<std::size_t>(n.leaf)];
        const double lo = std::max(ulo, axis.at(leaf.a0)), hi = std::min(uhi, axis.at(leaf.b0));
        if (hi > lo) out.push_back({n.leaf, s1, far, axis, leaf.a0, leaf.b0, lo, hi});
      }
    }

    // The coordinate in [-1, 1] of s0 on the piece's side [a0, b0] (root cell coordinates).
    static double leaf_coordinate(double a0, double b0, double s0) {
      return std::clamp((2.0 * s0 - a0 - b0) / (b0 - a0), -1.0, 1.0);
    }

    // The Chebyshev weights of piece `index` for the three channel degrees (kWeightRow each),
    // zero at the first reading in that piece.
    double* weights(int index, double s1) const {
      for (std::size_t i = 0; i < visits_.size(); ++i) {
        const std::size_t k = (last_visit_ + i) % visits_.size();
        if (visits_[k].leaf == index) {
          last_visit_ = k;
          return weights_.data() + visits_[k].offset;
        }
      }
      const std::size_t at = weights_.size();
      weights_.resize(at + 3 * kWeightRow, 0.0);
      last_visit_ = visits_.size();
      visits_.push_back({index, s1, at});
      return weights_.data() + at;
    }

    // The ray's sums, out, mirrored back to c's quadrant and added to acc with the readings
    // taken by channels_at.
    void finish(const double* out, double* acc) const {
      for (int j = 0; j < kChannels; ++j)
        acc[j] += ((fx_ && kOddX[j]) != (fy_ && kOddY[j]) ? -out[j] : out[j]) + direct_[j];
    }

    // Piece `index`'s coefficients summed against T_l(y) at angular coordinate s1: a radial
    // series of every channel, a[k kChannels + j].
    std::vector<double> reduce_piece(int index, double s1) const {
      const Leaf& leaf = t_->leaves_[static_cast<std::size_t>(index)];
      int len = 0;
      for (int l = 0; l <= leaf.n1; ++l)
        len = std::max(len, leaf.row_len[static_cast<std::size_t>(l)]);
      std::vector<double> a(static_cast<std::size_t>(len) * kChannels, 0.0);
      double ty[kStoreDegree + 1];
      chebyshev_values(leaf_coordinate(leaf.a1, leaf.b1, s1), leaf.n1, ty);
      const double* c = t_->coeff_.data() + leaf.offset;
      for (int l = 0; l <= leaf.n1; ++l) {
        const int row = leaf.row_len[static_cast<std::size_t>(l)];
        for (int k = 0; k < row; ++k, c += kChannels)
          for (int j = 0; j < kChannels; ++j)
            a[static_cast<std::size_t>(k * kChannels + j)] += ty[l] * c[j];
      }
      return a;
    }

    // Adds to out piece `index`'s coefficients summed against T_l(y) at angular coordinate s1 and
    // radial weights for channels of degree 0, 1 and 2 (w0, w1, w2; T_k(x) for one reading).
    void sum_piece(int index, double s1, const double* w0, const double* w1, const double* w2,
                   double* out) const {
      const Leaf& leaf = t_->leaves_[static_cast<std::size_t>(index)];
      double ty[kStoreDegree + 1];
      chebyshev_values(leaf_coordinate(leaf.a1, leaf.b1, s1), leaf.n1, ty);
      const double* c = t_->coeff_.data() + leaf.offset;
      for (int l = 0; l <= leaf.n1; ++l) {
        const int len = leaf.row_len[static_cast<std::size_t>(l)];
        for (int k = 0; k < len; ++k, c += kChannels) {
          const double a[3] = {ty[l] * w0[k], ty[l] * w1[k], ty[l] * w2[k]};
          for (int j = 0; j < kChannels; ++j) out[j] += a[SpotIntegrals::kChannelDegree[j]] * c[j];
        }
      }
    }

    const SpotIntegralTable* t_;
    double cx_, cy_;
    bool fx_ = false, fy_ = false, centre_ = false;
    double P_ = 0.0, r_ = 0.0;  // the reference radius and |c| at s = 1
    double u1_[2] = {};         // the angular coordinate in the polar and the far patch
    static constexpr std::size_t kUnset = static_cast<std::size_t>(-1);
    mutable std::size_t i1_[2] = {kUnset, kUnset};  // the angle's cell in each patch
    mutable int last_root_ = -1;                    // and its coordinate in that root cell
    mutable double last_s1_ = 0.0;
    // The last reading's patch, the radial range [lo, hi) of its root cell there, and its piece.
    mutable std::size_t last_patch_ = kUnset;
    mutable double last_lo_ = 0.0, last_hi_ = 0.0;
    mutable int last_leaf_ = -1;
    // add(): each piece read, its angular coordinate and the offset of its weights.
    struct Visit {
      int leaf;
      double s1;
      std::size_t offset;
    };
    static constexpr int kWeightRow = 17;  // kStoreDegree + 1
    mutable std::vector<Visit> visits_;
    mutable std::vector<double> weights_;
    mutable std::size_t last_visit_ = 0;
    mutable double direct_[kChannels] = {};  // readings by channels_at
  };

  Ray ray(double cx, double cy) const { return Ray(*this, cx, cy); }

  // Whether this table holds the integrals a model of this spot, aspect and law needs (the same
  // kind, the same q bit for bit, the same law and shape parameter; for a map the same map
  // object, whatever the law and q).
  bool matches(const ContactSpot& spot, double q, const PressureLaw<double>& law) const {
    if (spot.kind == SpotKind::Map || kind_ == SpotKind::Map)
      return spot.kind == kind_ && spot.map != nullptr && spot.map == map_;
    const SpotKind kind = spot.kind == SpotKind::Rect ? SpotKind::Rect : SpotKind::Ellipse;
    const double aspect = spot.has_aspect() ? q : 1.0;
    const bool shaped = law.kind == PressureKind::Power || law.kind == PressureKind::Annulus;
    return kind == kind_ && aspect == q_ && law.kind == law_.kind && (!shaped || law.n == law_.n) &&
           (law.kind != PressureKind::Table || law.table == law_.table);
  }

  SpotKind kind() const { return kind_; }
  double q() const { return q_; }
  const PressureLaw<double>& law() const { return law_; }

  struct Stats {
    std::size_t points = 0;  // integrals computed by the build (with the check points)
    // Those of the uniform ellipse's table that a table law's points came from; an annulus,
    // which reads that table, reports its points and pieces in both.
    std::size_t layer_points = 0;
    std::size_t pieces = 0;        // Chebyshev pieces stored
    std::size_t coefficients = 0;  // of each channel, summed over the pieces
    double estimate = 0.0;         // the build's own error estimate, worst cell, relative to A0
  };
  const Stats& stats() const { return stats_; }

 private:
  // --- Tolerances and grading (measured choices; see the header comment) ------------------------

  static constexpr double kSampleTolerance = 3e-11;  // interpolation error of a sampled cell / A0
  static constexpr double kCheckTolerance = 5e-11;   // the cell's check point / A0
  static constexpr double kStoreTolerance = 2e-11;   // dropped by the cut into pieces / A0
  static constexpr int kStartDegree = 8;
  // A map's cells between grid lines settle at degree 10 (make_map_roots) with the near cells
  // reaching kNearRing beyond those that touch them: 9 took 12 % more points on a rough random
  // grid, 11 3 % more and 8 (then 16) 60 % more. With only the touching cells held apart they
  // settled at 12 (9 then 18 took 20 % more points, 8 then 16 50 % more).
  static constexpr int kMapStartDegree = 10;
  int start_degree() const { return kind_ == SpotKind::Map ? kMapStartDegree : kStartDegree; }
  static constexpr int kMaxSampleDegree = 64;
  static constexpr int kStoreDegree = 16;
  static_assert(Ray::kWeightRow == kStoreDegree + 1, "a ray's weights hold a piece's degrees");
  static constexpr int kMaxDepth = 24;
  static constexpr double kMaxRate = 0.95;  // slowest decay the error estimate assumes
  static constexpr double kSafety = 1.1;    // on the degree extrapolated for a cell
  static constexpr double kNear = 1.5;      // R_near / max |r| over the spot
  static constexpr double kGraded = 0.35;   // width of the graded cells next to a line
  static constexpr double kRatio = 6.0;     // a linear cell's width / its distance from a line
  static constexpr double kCornerRadius = 0.5;
  static constexpr double kCornerInset = 0.7;       // graded width / corner radius (< 1/sqrt 2)
  static constexpr double kCornerAngle = M_PI / 4;  // graded angle next to a line's direction
  static constexpr double kSqueeze = 0.3;  // grade the reference angle when atanh(q) is smaller
  static constexpr double kSqueezeTable = 0.11;  // the same for a table law (reference_quarter)
  static constexpr double kConfocal = 0.3;  // outside an ellipse of aspect below: confocal patch
  static constexpr double kPolarLayers = 0.05;    // but for layers, down to this aspect
  static constexpr double kSourceTighter = 0.03;  // the confocal table that layers' points read
  static constexpr std::size_t kMaxGradedBreaks = 8;
  static constexpr std::size_t kPlainKinks = 64;  // fewer: every kink a cell boundary (make_roots)
  // A map's near cells (make_near_nodes): those that touch a root cell and this many rings more.
  static constexpr std::size_t kNearRing = 1;

  // Which channels change sign with c_x and with c_y.
  static constexpr bool kOddX[kChannels] = {false, true, false, true,  false, true,
                                            false, true, false, false, true,  false};
  static constexpr bool kOddY[kChannels] = {true,  true,  false, false, false, true,
                                            false, false, true,  false, false, true};

  // --- The table --------------------------------------------------------------------------------

  enum class Coords { Polar, Box, Corner, Far, Confocal };

  struct Root {
    int patch;
    Axis a0, a1;
    int tree;  // its node in tree_
  };

  // A binary tree per root: an inner node halves one s-coordinate at `mid`; a leaf names a piece.
  struct TreeNode {
    int dir = -1;  // -1: a leaf
    double mid = 0.0;
    int child[2] = {-1, -1};
    int leaf = -1;
  };

  // A stored piece: a box in its root's s-coordinates and, per row l of its series, row_len[l]
  // coefficients of every channel (coefficient k of channel j at offset + (k' + k) * 12 + j).
  struct Leaf {
    double a0, b0, a1, b1;
    int n0, n1;
    std::size_t offset;
    std::vector<int> row_len;
  };

  struct Patch {
    Coords coords;
    double x0 = 0.0, y0 = 0.0, radius = 0.0;  // a corner patch: its centre and radius
    std::vector<double> breaks0, breaks1;     // the root cells' bounds in the patch coordinates
    std::vector<int> roots;                   // into roots_, breaks0-major; -1: inside a corner

    explicit Patch(Coords c, double x = 0.0, double y = 0.0, double r = 0.0)
        : coords(c), x0(x), y0(y), radius(r) {}
  };

  // The physical centre of rotation of a patch point.
  void centre(const Patch& p, double u0, double u1, double& cx, double& cy) const {
    switch (p.coords) {
      case Coords::Polar:
        cx = u0 * std::cos(u1);
        cy = q_ * u0 * std::sin(u1);
        return;
      case Coords::Box:
        cx = u0;
        cy = u1;
        return;
      case Coords::Corner:
        cx = p.x0 + u0 * std::cos(u1);
        cy = p.y0 + u0 * std::sin(u1);
        return;
      case Coords::Far:
        cx = p.x0 + std::cos(u1) / u0;
        cy = p.y0 + std::sin(u1) / u0;
        return;
      case Coords::Confocal:
        cx = focal_ * std::cosh(u0) * std::cos(u1);
        cy = focal_ * std::sinh(u0) * std::sin(u1);
        return;
    }
  }

  // The patch of a centre in the first quadrant (index into patches_), and its coordinates.
  template <typename E>
  std::size_t coordinates(const E& ax, const E& ay, E& u0, E& u1) const {
    using std::atan2;
    using std::hypot;
    if (kind_ == SpotKind::Map) {
      const Patch& box = patches_[0];
      if (ax >= box.breaks0.front() && ax <= box.breaks0.back() && ay >= box.breaks1.front() &&
          ay <= box.breaks1.back()) {
        u0 = ax;
        u1 = ay;
        return 0;
      }
      const Patch& far = patches_[1];
      const E r = hypot(ax - far.x0, ay - far.y0);
      u0 = r < HUGE_VAL ? E(1.0 / r) : E(0.0);
      u1 = atan2(ay - far.y0, ax - far.x0);
      return 1;
    }
    if (kind_ == SpotKind::Ellipse) {
      const E X = ax, Y = ay / q_, P = hypot(X, Y);
      if (P <= near_) {
        u0 = P;
        u1 = P > 0.0 ? E(atan2(Y, X)) : E(0.0);
        return 0;
      }
      if (confocal_ && confocal(ax, ay, u0, u1)) return 2;
    } else if (ax <= near_ && ay <= near_) {
      for (std::size_t i = 2; i < patches_.size(); ++i) {
        const Patch& p = patches_[i];
        const E dx = ax - p.x0, dy = ay - p.y0;
        if (dx * dx + dy * dy < p.radius * p.radius) {
          u0 = hypot(dx, dy);
          u1 = u0 > 0.0 ? E(atan2(dy, dx)) : E(0.0);
          return i;
        }
      }
      u0 = ax;
      u1 = ay;
      return 0;
    }
    const E r = hypot(ax, ay);
    u0 = r < HUGE_VAL ? E(1.0 / r) : E(0.0);
    u1 = atan2(ay, ax);
    return 1;
  }

  // The confocal coordinates (mu, nu) of (ax, ay) in the first quadrant, x = f cosh mu cos nu,
  // y = f sinh mu sin nu, if mu is within the patch. B = f sinh mu solves
  // B^4 - (r^2 - f^2) B^2 - f^2 y^2 = 0 (r = |c|), taken in the form without cancellation.
  template <typename E>
  bool confocal(const E& ax, const E& ay, E& mu, E& nu) const {
    using std::atan2;
    using std::log1p;
    using std::sqrt;
    const double f2 = focal_ * focal_;
    const E d = ax * ax + ay * ay - f2, root = sqrt(d * d + 4.0 * f2 * ay * ay);
    const E B2 = d >= 0.0 ? E(0.5 * (d + root)) : E(2.0 * f2 * ay * ay / (root - d));
    const E b = sqrt(B2) / focal_, a = sqrt(1.0 + b * b);  // sinh mu, cosh mu
    const E m = log1p(b + b * b / (1.0 + a));
    if (!(value_of(m) <= mu_far_)) return false;
    mu = m;
    nu = atan2(ay / b, ax / a);
    return true;
  }

  // Whether Ray may read pieces by slices: an ellipse's own table (not an annulus' pair).
  bool ray_by_slices() const { return kind_ == SpotKind::Ellipse && !uniform_; }

  // The limit |c| -> inf in direction gamma (sliding_limit_integrals), as channels.
  std::array<double, kChannels> far_limit(double gamma) const {
    return sliding_limit_integrals(SpotMoments<double>{A0_, Ax_, Ay_, Axx_, Axy_, Ayy_}, gamma)
        .channels();
  }

  template <typename E>
  void evaluate(const E& ax, const E& ay, E* v) const {
    E u0, u1;
    const Patch& g = patches_[coordinates(ax, ay, u0, u1)];
    const std::size_t i0 = locate(g.breaks0, value_of(u0)), i1 = locate(g.breaks1, value_of(u1));
    const int r = g.roots[i0 * (g.breaks1.size() - 1) + i1];
    if (r < 0) {  // inside a corner's disk by construction; only rounding can land here
      for (int j = 0; j < kChannels; ++j) v[j] = E(std::nan(""));
      return;
    }
    const Root& root = roots_[static_cast<std::size_t>(r)];
    const E s0 = root.a0.s_of(u0), s1 = root.a1.s_of(u1);
    const TreeNode* node = &tree_[static_cast<std::size_t>(root.tree)];
    while (node->dir >= 0)
      node = &tree_[static_cast<std::size_t>(node->child[(node->dir == 0 ? s0 : s1) >= node->mid])];
    const Leaf& leaf = leaves_[static_cast<std::size_t>(node->leaf)];
    const E x =
        std::clamp(E((2.0 * s0 - leaf.a0 - leaf.b0) / (leaf.b0 - leaf.a0)), E(-1.0), E(1.0));
    const E y =
        std::clamp(E((2.0 * s1 - leaf.a1 - leaf.b1) / (leaf.b1 - leaf.a1)), E(-1.0), E(1.0));
    E tx[kStoreDegree + 1], ty[kStoreDegree + 1];
    chebyshev_values(x, leaf.n0, tx);
    chebyshev_values(y, leaf.n1, ty);
    E acc[kChannels] = {};
    const double* c = coeff_.data() + leaf.offset;
    for (int l = 0; l <= leaf.n1; ++l) {
      E row[kChannels] = {};
      const int len = leaf.row_len[static_cast<std::size_t>(l)];
      for (int k = 0; k < len; ++k, c += kChannels)
        for (int j = 0; j < kChannels; ++j) row[j] += tx[k] * c[j];
      for (int j = 0; j < kChannels; ++j) acc[j] += ty[l] * row[j];
    }
    if (!near_nodes_.empty()) add_near(r, ax, ay, acc);
    for (int j = 0; j < kChannels; ++j) v[j] = acc[j];
  }

  // A map's near cells (near_nodes_) of root cell r at c, added to acc by their corner sums. A
  // dual number's parts along c come from one PlaneDual instantiation of the sums, by the chain
  // rule (plane_dual.hpp).
  template <typename E>
  void add_near(int r, const E& cx, const E& cy, E* acc) const {
    const std::vector<MapCornerNode>& nodes = near_nodes_[static_cast<std::size_t>(r)];
    if (nodes.empty()) return;
    if constexpr (std::is_same_v<E, double>) {
      MapCornerMoments moments(cx, cy);
      for (const MapCornerNode& n : nodes) moments.add(n);
      moments.add_channels(acc);
    } else {
      const double x = value_of(cx), y = value_of(cy);
      BasicMapCornerMoments<PlaneDual> moments(PlaneDual(x, 1.0, 0.0), PlaneDual(y, 0.0, 1.0));
      for (const MapCornerNode& n : nodes) moments.add(n);
      PlaneDual sums[kChannels];
      moments.add_channels(sums);
      const E along_x = cx - x, along_y = cy - y;  // c's parts, its value taken out
      for (int j = 0; j < kChannels; ++j)
        acc[j] += sums[j].v + sums[j].dx * along_x + sums[j].dy * along_y;
    }
  }

  // A map's integrals are not smooth across the edges of its grid cells (sigma0 kinks there,
  // d^3 ln d, or jumps at the map's edges, d^2 ln d), but only those of the cells whose closure
  // a root cell's closure meets reach it: the others' edges keep at least a grid cell away. So
  // each root cell of the box holds the integrals less those cells' and of the ring of cells
  // about them (its near cells: up to 5 x 5 about a grid cell, two rows of the edge's cells
  // next to one outside), whose corner sums are exact wherever c lies and cost 0.6-0.9 us a
  // reading. What it holds is then analytic on it with its nearest singular line two grid cells
  // away, not one: degree 10 each way where the touching cells alone left 12, and on a rough
  // 30 x 30 grid half the points.
  void make_near_nodes(const MapStripIntegrator& strips) {
    const PressureMap& m = *map_;
    near_nodes_.assign(roots_.size(), {});
    // The grid cells [lo, hi) whose closed interval meets [a, b] along one axis.
    auto touching = [](const std::vector<double>& g, double a, double b, std::size_t& lo,
                       std::size_t& hi) {
      lo = g.size();
      hi = 0;
      for (std::size_t i = 0; i + 1 < g.size(); ++i)
        if (g[i] <= b && g[i + 1] >= a) {
          lo = std::min(lo, i);
          hi = i + 1;
        }
      if (lo >= hi) lo = hi = 0;
    };
    for (std::size_t r = 0; r < roots_.size(); ++r) {
      const Root& root = roots_[r];
      if (patches_[static_cast<std::size_t>(root.patch)].coords != Coords::Box) continue;
      std::size_t i0, i1, j0, j1;
      touching(m.x, root.a0.lo, root.a0.hi, i0, i1);
      touching(m.y, root.a1.lo, root.a1.hi, j0, j1);
      if (!(i1 > i0 && j1 > j0)) continue;
      // And one grid cell more on every side (kNearRing).
      i0 -= std::min(i0, kNearRing);
      j0 -= std::min(j0, kNearRing);
      i1 = std::min(m.x.size() - 1, i1 + kNearRing);
      j1 = std::min(m.y.size() - 1, j1 + kNearRing);
      near_nodes_[r] = strips.corner_nodes(i0, i1, j0, j1);
    }
  }

  static std::size_t locate(const std::vector<double>& breaks, double u) {
    const auto it = std::upper_bound(breaks.begin() + 1, breaks.end() - 1, u);
    return static_cast<std::size_t>(it - breaks.begin()) - 1;
  }

  // --- Root cells -------------------------------------------------------------------------------

  // The cells of one coordinate over [lo, hi]: graded cells of the given widths on both sides of
  // every singular point (ascending, inside (lo, hi]), linear cells between them no wider than
  // kRatio times their distance from the nearest one. Plain points (ascending) are cell
  // boundaries too, ungraded: the graded cells stop at them and the linear cells are cut there.
  static std::vector<Axis> axis_cells(double lo, double hi, const std::vector<double>& singular,
                                      const std::vector<double>& widths, int power,
                                      const std::vector<double>& plain = {}) {
    std::vector<Axis> out;
    std::vector<std::pair<double, double>> gaps;
    double from = lo;
    for (std::size_t i = 0; i < singular.size(); ++i) {
      const double s = singular[i];
      const double prev = i == 0 ? lo : singular[i - 1];
      const double next = i + 1 == singular.size() ? hi : singular[i + 1];
      double left = std::min(widths[i], (i == 0 ? 1.0 : 0.5) * (s - prev));
      double right = std::min(widths[i], (i + 1 == singular.size() ? 1.0 : 0.5) * (next - s));
      const auto above = std::upper_bound(plain.begin(), plain.end(), s);
      if (above != plain.end()) right = std::min(right, *above - s);
      const auto below = std::lower_bound(plain.begin(), plain.end(), s);
      if (below != plain.begin()) left = std::min(left, s - *(below - 1));
      if (left > 0.0) {
        gaps.push_back({from, s - left});
        out.push_back(Axis{s - left, s, power, true});
      }
      if (right > 0.0) out.push_back(Axis{s, s + right, power, false});
      from = s + right;
    }
    gaps.push_back({from, hi});
    if (!plain.empty()) {
      std::vector<std::pair<double, double>> cut;
      for (auto [a, e] : gaps) {
        for (double u : plain)
          if (u > a && u < e) {
            cut.push_back({a, u});
            a = u;
          }
        cut.push_back({a, e});
      }
      gaps = std::move(cut);
    }
    auto distance = [&](double u) {
      double d = HUGE_VAL;
      for (double s : singular) d = std::min(d, std::fabs(u - s));
      return d;
    };
    for (auto [a, e] : gaps) {
      std::vector<std::pair<double, double>> stack = {{a, e}};
      while (!stack.empty()) {
        const auto [x, y] = stack.back();
        stack.pop_back();
        if (!(y > x)) continue;
        const double dx = distance(x), dy = distance(y);
        if (y - x > kRatio * std::min(dx, dy) && y - x > 1e-3) {
          const double m = dx < dy ? x + (y - x) / 3.0 : y - (y - x) / 3.0;
          stack.push_back({x, m});
          stack.push_back({m, y});
        } else {
          out.push_back(Axis{x, y, 1, true});
        }
      }
    }
    std::sort(out.begin(), out.end(), [](const Axis& p, const Axis& r) { return p.lo < r.lo; });
    return out;
  }

  // The cells of the angle about a corner, [-pi, pi], graded towards every singular direction
  // (ascending, the first -pi, standing for pi too).
  static std::vector<Axis> angle_cells(const std::vector<double>& dirs, int power) {
    std::vector<Axis> out;
    for (std::size_t i = 0; i < dirs.size(); ++i) {
      const double a = dirs[i], b = i + 1 < dirs.size() ? dirs[i + 1] : M_PI;
      const double g = std::min(0.5 * (b - a), kCornerAngle);
      out.push_back(Axis{a, a + g, power, false});
      const int parts = static_cast<int>(std::ceil((b - a - 2.0 * g) / (0.5 * M_PI) - 1e-9));
      for (int k = 0; k < parts; ++k)
        out.push_back(Axis{a + g + (b - a - 2.0 * g) * k / parts,
                           a + g + (b - a - 2.0 * g) * (k + 1) / parts, 1, true});
      out.push_back(Axis{b - g, b, power, true});
    }
    return out;
  }

  // The quarter turn of the ellipse's reference angle: the rim's normal and the physical direction
  // turn on the scale atanh(min(q, 1/q)) about the axes (branch points that far off the real
  // line), so the cells are graded geometrically towards both ends at that scale when it is
  // small. A table law's own table only from a smaller scale: its every band between two
  // samples is a row of cells across the angle, and each graded cell a band's least degree
  // more (41 samples at q = 0.2: 38,073 points graded, 25,801 not; at 4 33,988 for 43,477; 201
  // samples 1.6-2.2x fewer at q = 0.15-0.25 and 3.5-4). Below, the grading pays again (41
  // samples at q = 0.08: 57,233 graded, 70,986 not).
  std::vector<Axis> reference_quarter() const {
    const double scale = std::atanh(std::min(q_, 1.0 / q_));
    std::vector<double> b = {0.0, 0.5 * M_PI};
    if (scale < (law_.kind == PressureKind::Table ? kSqueezeTable : kSqueeze))
      for (double w = scale; w < 0.25 * M_PI; w *= 3.0) {
        b.push_back(w);
        b.push_back(0.5 * M_PI - w);
      }
    std::sort(b.begin(), b.end());
    std::vector<Axis> out;
    for (std::size_t i = 0; i + 1 < b.size(); ++i) out.push_back(Axis{b[i], b[i + 1], 1, true});
    return out;
  }

  void add_patch(Patch p, const std::vector<Axis>& c0, const std::vector<Axis>& c1,
                 const std::function<bool(const Axis&, const Axis&)>& skip = {}) {
    for (const Axis& a : c0) p.breaks0.push_back(a.lo);
    p.breaks0.push_back(c0.back().hi);
    for (const Axis& a : c1) p.breaks1.push_back(a.lo);
    p.breaks1.push_back(c1.back().hi);
    const int index = static_cast<int>(patches_.size());
    for (const Axis& a : c0)
      for (const Axis& b : c1) {
        if (skip && skip(a, b)) {
          p.roots.push_back(-1);
          continue;
        }
        p.roots.push_back(static_cast<int>(roots_.size()));
        roots_.push_back(Root{index, a, b, static_cast<int>(tree_.size())});
        tree_.push_back(TreeNode{});
      }
    patches_.push_back(std::move(p));
  }

  // A map (docs/physics.md §9.1): every grid line is a cell boundary, each interval between two
  // lines one root cell, and outside the grid one cell out to the box that holds the disk
  // |c - centre| <= R_near. None is graded: a root cell holds the integrals less those of its
  // near cells (make_near_nodes), which is analytic on it, the next grid cell's edges two grid
  // cells away (the integrals themselves go like d^3 ln d across the lines, where sigma0 kinks,
  // and d^2 ln d across the edges, where it jumps: graded towards both, a cell took degree 18
  // each way where it now takes 10, and the outside cells take 10 along the edge and 36 away
  // from it; split in two away from the edge, at one, two or four grid cells, they took 16-23 %
  // more points on a rough 15 x 15 grid, up to 55 % on the footprint). The far patch turns about
  // the map's centre.
  void make_map_roots() {
    const PressureMap& m = *map_;
    const double mx = 0.5 * (m.x.front() + m.x.back()), my = 0.5 * (m.y.front() + m.y.back());
    near_ = kNear * std::hypot(0.5 * (m.x.back() - m.x.front()), 0.5 * (m.y.back() - m.y.front()));
    auto cells = [this](const std::vector<double>& grid, double centre) {
      std::vector<Axis> out;
      auto outside = [&out](double edge, double to) {  // one cell from the edge out
        out.push_back(to > edge ? Axis{edge, to, 1, false} : Axis{to, edge, 1, true});
      };
      outside(grid.front(), centre - near_);
      for (std::size_t i = 0; i + 1 < grid.size(); ++i)
        out.push_back(Axis{grid[i], grid[i + 1], 1, true});
      outside(grid.back(), centre + near_);
      std::sort(out.begin(), out.end(), [](const Axis& p, const Axis& r) { return p.lo < r.lo; });
      return out;
    };
    add_patch(Patch(Coords::Box), cells(m.x, mx), cells(m.y, my));
    std::vector<Axis> turn;
    for (int k = 0; k < 4; ++k)
      turn.push_back(Axis{-M_PI + 0.5 * M_PI * k, -M_PI + 0.5 * M_PI * (k + 1), 1, true});
    add_patch(Patch(Coords::Far, mx, my), {Axis{0.0, 1.0 / near_, 1, true}}, turn);
  }

  void make_roots() {
    if (kind_ == SpotKind::Map) {
      make_map_roots();
      return;
    }
    // The lines |x| = B (rectangle) or P = B (ellipse) where sigma0 jumps or kinks, and the rim.
    // A table's every sample is a kink (its interpolant is only C^1 there): beyond a few, its
    // steps are graded, on an ellipse its strongest kinks too (at an extremum, where the
    // interpolant flattens: 3e-10 A0 -> 4e-12 for 201 samples; on a rectangle every graded line
    // adds two corners, 4x the points), and the other kinks left to the cells (below).
    std::vector<double> lines;
    const std::vector<double> breaks = law_.breakpoints();
    std::vector<double> graded = breaks.size() <= kMaxGradedBreaks ? breaks : law_.steps();
    if (breaks.size() > kMaxGradedBreaks && kind_ == SpotKind::Ellipse)
      for (const PressureTable::Kink& k : law_.table->kinks())
        if (graded.size() < kMaxGradedBreaks) graded.push_back(k.rho);
    for (double b : graded)
      if (b > 0.0 && b < 1.0) lines.push_back(b);
    lines.push_back(1.0);
    std::sort(lines.begin(), lines.end());
    // On an ellipse a table of fewer than kPlainKinks samples has its other kinks as plain cell
    // boundaries: left inside the cells (d^4 ln d within, not at an end) they took degrees up
    // to 64 and halvings across every band between samples (41 samples at aspect 0.7: 16,135
    // points, now 12,152; at 4 66,109 and 43,477). Many close samples kink less each; there the
    // cells' degrees take them (201 samples: 9,000 points, with every kink a boundary 40,000).
    std::vector<double> plain;
    if (kind_ == SpotKind::Ellipse && breaks.size() > kMaxGradedBreaks &&
        breaks.size() < kPlainKinks)
      for (double b : breaks)
        if (b > 0.0 && b < 1.0 && !std::binary_search(lines.begin(), lines.end(), b))
          plain.push_back(b);
    plain.erase(std::unique(plain.begin(), plain.end()), plain.end());
    const bool ring = law_.kind == PressureKind::Ring;
    const int power = ring ? 4 : 3, corner_power = ring ? 6 : 3;
    const double max_r = kind_ == SpotKind::Ellipse ? std::max(1.0, q_) : std::hypot(1.0, q_);
    const double far = kNear * max_r;
    const std::vector<Axis> quarter = {Axis{0.0, 0.5 * M_PI, 1, true}};
    const std::vector<Axis> inverse = {Axis{0.0, 1.0 / far, 1, true}};
    if (kind_ == SpotKind::Ellipse) {
      // The polar patch reaches every point nearer than R_near; on an elongated ellipse only
      // the spot itself, and the confocal patch the rest (below).
      confocal_ = q_ < kConfocal && !polar_;
      near_ = confocal_ ? 1.0 : far / std::min(1.0, q_);
      add_patch(
          Patch(Coords::Polar),
          axis_cells(0.0, near_, lines, std::vector<double>(lines.size(), kGraded), power, plain),
          reference_quarter());
      add_patch(Patch(Coords::Far), inverse, quarter);
      if (confocal_) {
        // Outside an ellipse of aspect q < 1, confocal coordinates about its foci (+-f, 0),
        // f = sqrt(1 - q^2): the rim is mu = atanh(q), and they are conformal, so a cell square
        // in them is square on the plane, where the integrals vary alike both ways. In the
        // reference polar coordinates the cells along the long sides were 1/q times longer
        // along the rim than across it, and the table grew as 1/q. The patch reaches the
        // confocal ellipse whose minor semi-axis is R_near, beyond which the far patch takes
        // over; its angle is graded towards the tips at the rim's scale there, atanh(q).
        focal_ = std::sqrt((1.0 - q_) * (1.0 + q_));
        const double mu_rim = std::atanh(q_);
        mu_far_ = std::asinh(far / focal_);
        std::vector<double> b = {0.0, 0.5 * M_PI};
        for (double w = mu_rim; w < 0.25 * M_PI; w *= 3.0) b.push_back(w);
        std::sort(b.begin(), b.end());
        std::vector<Axis> turn;
        for (std::size_t i = 0; i + 1 < b.size(); ++i)
          turn.push_back(Axis{b[i], b[i + 1], 1, true});
        add_patch(Patch(Coords::Confocal), axis_cells(mu_rim, mu_far_, {mu_rim}, {kGraded}, power),
                  turn);
      }
      return;
    }
    // The corners (x, q) of the lines with the edge y = q, each the centre of a disk of polar
    // coordinates reaching halfway to the next singular line.
    near_ = far;
    std::vector<Patch> corners;
    std::vector<double> widths;
    double y_width = kGraded;
    for (double x : lines) {
      double radius = std::min(kCornerRadius, q_);
      for (double o : lines) {
        if (o != x) radius = std::min(radius, 0.5 * std::fabs(o - x));
        radius = std::min(radius, 0.5 * (o + x));  // the mirror image -o
      }
      corners.push_back(Patch(Coords::Corner, x, q_, radius));
      widths.push_back(std::min(kGraded, kCornerInset * radius));
      y_width = std::min(y_width, kCornerInset * radius);
    }
    auto in_a_corner = [&](const Axis& a, const Axis& b) {
      for (const Patch& c : corners) {
        bool all = true;
        for (double X : {a.lo, a.hi})
          for (double Y : {b.lo, b.hi}) all = all && std::hypot(X - c.x0, Y - c.y0) < c.radius;
        if (all) return true;
      }
      return false;
    };
    add_patch(Patch(Coords::Box), axis_cells(0.0, near_, lines, widths, power),
              axis_cells(0.0, near_, {q_}, {y_width}, power), in_a_corner);
    add_patch(Patch(Coords::Far), inverse, quarter);
    for (const Patch& c : corners) {
      std::vector<double> dirs = {-M_PI, -0.5 * M_PI};  // along the edge inwards, down the line
      if (c.x0 < 1.0) dirs.push_back(0.0);              // the edge goes on outwards
      add_patch(c, {Axis{0.0, c.radius, corner_power, false}}, angle_cells(dirs, power));
    }
  }

  // --- The build --------------------------------------------------------------------------------

  using Values = std::array<double, kChannels>;

  // The Chebyshev coefficients of one box: (n1 + 1) rows of (n0 + 1), each kChannels wide.
  struct Series {
    int n0 = 0, n1 = 0;
    std::vector<Values> c;
    const Values& at(int k, int l) const { return c[static_cast<std::size_t>(l * (n0 + 1) + k)]; }
    Values& at(int k, int l) { return c[static_cast<std::size_t>(l * (n0 + 1) + k)]; }
  };

  // A box of a root, in its s-coordinates, sampled on the extreme points of degree (n0, n1).
  struct Cell {
    int root;
    double a0, b0, a1, b1;
    int n0, n1;
    std::vector<Values> values;  // (n1 + 1) x (n0 + 1), row j = point y_j
    std::vector<char> known;
    Values check{};
    bool check_known = false;
    int depth = 0;
    int tree;  // its node in tree_
  };

  static double node(int i, int n) {
    if (2 * i == n) return 0.0;
    return i == 0 ? 1.0 : i == n ? -1.0 : std::cos(M_PI * i / n);
  }
  static double lerp(double a, double b, double x) {
    return x == 1.0 ? b : x == -1.0 ? a : 0.5 * (a + b) + 0.5 * (b - a) * x;
  }

  // The discrete Chebyshev transform on the extreme points of degree n (1 to 64): coefficient k
  // of the interpolant is sum_i M[k][i] f(x_i).
  static const std::vector<double>& dct_matrix(int n) {
    static const std::vector<std::vector<double>> m = [] {
      std::vector<std::vector<double>> all(kMaxSampleDegree + 1);
      for (int k = 1; k <= kMaxSampleDegree; ++k) all[static_cast<std::size_t>(k)] = make_dct(k);
      return all;
    }();
    return m[static_cast<std::size_t>(n)];
  }
  static std::vector<double> make_dct(int n) {
    std::vector<double> m(static_cast<std::size_t>((n + 1) * (n + 1)));
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= n; ++i) {
        const double w = (i == 0 || i == n) ? 0.5 : 1.0;
        m[static_cast<std::size_t>(k * (n + 1) + i)] =
            w * std::cos(M_PI * static_cast<double>((k * i) % (2 * n)) / n) *
            ((k == 0 || k == n) ? 1.0 : 2.0) / n;
      }
    return m;
  }

  // One line of the transform: out[k out_stride] = sum_i M[k][i] f[i stride], i, k = 0..n. As
  // M[k][n - i] = (-1)^k M[k][i], the sums run over half the line, against f_i + f_(n-i) for
  // even k and f_i - f_(n-i) for odd k: half the products (the transform took a tenth of a
  // table law's build).
  static void dct_line(const std::vector<double>& m, int n, const Values* f, std::size_t stride,
                       Values* out, std::size_t out_stride) {
    const int pairs = (n + 1) / 2;  // i < n - i
    Values sum[kMaxSampleDegree / 2 + 1], diff[kMaxSampleDegree / 2 + 1];
    for (int i = 0; i < pairs; ++i) {
      const Values& a = f[static_cast<std::size_t>(i) * stride];
      const Values& b = f[static_cast<std::size_t>(n - i) * stride];
      for (std::size_t ch = 0; ch < kChannels; ++ch) {
        sum[i][ch] = a[ch] + b[ch];
        diff[i][ch] = a[ch] - b[ch];
      }
    }
    const bool middle = n % 2 == 0;  // f_(n/2) pairs with itself
    for (int k = 0; k <= n; ++k) {
      const double* row = m.data() + static_cast<std::size_t>(k * (n + 1));
      const Values* half = k % 2 == 0 ? sum : diff;
      Values acc{};
      for (int i = 0; i < pairs; ++i)
        for (std::size_t ch = 0; ch < kChannels; ++ch) acc[ch] += row[i] * half[i][ch];
      if (middle) {
        const Values& c = f[static_cast<std::size_t>(n / 2) * stride];
        for (std::size_t ch = 0; ch < kChannels; ++ch) acc[ch] += row[n / 2] * c[ch];
      }
      out[static_cast<std::size_t>(k) * out_stride] = acc;
    }
  }

  static Series transform(const std::vector<Values>& values, int n0, int n1) {
    Series tmp{n0, n1, std::vector<Values>(values.size())}, out = tmp;
    const std::vector<double>& m0 = dct_matrix(n0);
    const std::vector<double>& m1 = dct_matrix(n1);
    const std::size_t row = static_cast<std::size_t>(n0 + 1);
    for (int j = 0; j <= n1; ++j)  // along x: tmp(k, j)
      dct_line(m0, n0, values.data() + static_cast<std::size_t>(j) * row, 1, &tmp.at(0, j), 1);
    for (int k = 0; k <= n0; ++k)  // along y: out(k, l)
      dct_line(m1, n1, &tmp.at(k, 0), row, &out.at(k, 0), row);
    return out;
  }

  // A series' values on the extreme points of its own degree over the sub-box [x0, x1] x [y0, y1]
  // of local coordinates: with transform(), its exact re-expansion there.
  static std::vector<Values> resample(const Series& s, double x0, double x1, double y0, double y1) {
    const int m0 = s.n0, m1 = s.n1;
    std::vector<Values> rows(static_cast<std::size_t>((m0 + 1) * (s.n1 + 1)));
    std::vector<double> t(static_cast<std::size_t>(std::max(s.n0, s.n1) + 1));
    for (int i = 0; i <= m0; ++i) {
      chebyshev_values(lerp(x0, x1, node(i, m0)), s.n0, t.data());
      for (int l = 0; l <= s.n1; ++l) {
        Values r{};
        for (int k = 0; k <= s.n0; ++k) {
          const Values& c = s.at(k, l);
          for (std::size_t ch = 0; ch < kChannels; ++ch)
            r[ch] += t[static_cast<std::size_t>(k)] * c[ch];
        }
        rows[static_cast<std::size_t>(l * (m0 + 1) + i)] = r;
      }
    }
    std::vector<Values> out(static_cast<std::size_t>((m0 + 1) * (m1 + 1)));
    for (int j = 0; j <= m1; ++j) {
      chebyshev_values(lerp(y0, y1, node(j, m1)), s.n1, t.data());
      for (int i = 0; i <= m0; ++i) {
        Values v{};
        for (int l = 0; l <= s.n1; ++l) {
          const Values& r = rows[static_cast<std::size_t>(l * (m0 + 1) + i)];
          for (std::size_t ch = 0; ch < kChannels; ++ch)
            v[ch] += t[static_cast<std::size_t>(l)] * r[ch];
        }
        out[static_cast<std::size_t>(j * (m0 + 1) + i)] = v;
      }
    }
    return out;
  }

  static Values sum(const Series& s, double x, double y) {
    std::vector<double> tx(static_cast<std::size_t>(s.n0 + 1)),
        ty(static_cast<std::size_t>(s.n1 + 1));
    chebyshev_values(x, s.n0, tx.data());
    chebyshev_values(y, s.n1, ty.data());
    Values v{};
    for (int l = 0; l <= s.n1; ++l)
      for (int k = 0; k <= s.n0; ++k)
        for (std::size_t ch = 0; ch < kChannels; ++ch)
          v[ch] +=
              tx[static_cast<std::size_t>(k)] * ty[static_cast<std::size_t>(l)] * s.at(k, l)[ch];
    return v;
  }

  struct Builder {
    SpotIntegralTable& t;
    const SpotIntegrator& integrate;
    const RectStripIntegrator& strips;
    const MapStripIntegrator& map_strips;
    const EllipseLawIntegrator<SpotIntegralTable>* layers;  // a table law on an ellipse
    const SpotIntegralTable* confocal;
    const std::function<bool()>& stop;
    const SpotParallelFor& parallel;
    std::size_t max_points;

    static constexpr double kCheckX = 0.2871, kCheckY = -0.6233;  // between the extreme points

    // A point by its patch and patch coordinates: cells that share an edge share its points.
    struct Key {
      int patch;
      double u0, u1;
      bool operator==(const Key& o) const { return patch == o.patch && u0 == o.u0 && u1 == o.u1; }
    };
    struct KeyHash {
      std::size_t operator()(const Key& k) const {
        std::uint64_t a, b;
        std::memcpy(&a, &k.u0, sizeof a);
        std::memcpy(&b, &k.u1, sizeof b);
        std::uint64_t z = a ^ (b * 0x9e3779b97f4a7c15ULL) ^ static_cast<std::uint64_t>(k.patch);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return static_cast<std::size_t>(z ^ (z >> 31));
      }
    };
    std::unordered_map<Key, Values, KeyHash> known;

    void run() {
      t.make_roots();
      // A first round beyond the budget is known from the root cells alone: each holds
      // (n - 1)^2 interior points and its check point, which no other cell shares. (A map of
      // 64 x 64 cells then gives up at once, where its near cells and first cells took 0.2 s.)
      const std::size_t inner = static_cast<std::size_t>(t.start_degree() - 1);
      if (t.roots_.size() * (inner * inner + 1) > max_points) throw SpotTableOverBudget();
      if (t.kind_ == SpotKind::Map) t.make_near_nodes(map_strips);
      std::vector<Cell> pending;
      for (std::size_t r = 0; r < t.roots_.size(); ++r) {
        Cell c;
        c.root = static_cast<int>(r);
        c.a0 = c.a1 = -1.0;
        c.b0 = c.b1 = 1.0;
        c.n0 = c.n1 = t.start_degree();
        c.tree = t.roots_[r].tree;
        resize(c);
        pending.push_back(std::move(c));
      }
      while (!pending.empty()) {
        evaluate_points(pending);
        std::vector<Cell> next;
        for (Cell& c : pending) decide(c, next);
        pending = std::move(next);
      }
      t.stats_.pieces = t.leaves_.size();
      t.stats_.coefficients = t.coeff_.size() / kChannels;
    }

    static void resize(Cell& c) {
      c.values.assign(static_cast<std::size_t>((c.n0 + 1) * (c.n1 + 1)), Values{});
      c.known.assign(c.values.size(), 0);
    }

    Key key_of(const Cell& c, double x, double y) const {
      const Root& root = t.roots_[static_cast<std::size_t>(c.root)];
      Key k{root.patch, root.a0.at(lerp(c.a0, c.b0, x)), root.a1.at(lerp(c.a1, c.b1, y))};
      const Coords coords = t.patches_[static_cast<std::size_t>(k.patch)].coords;
      if (k.u0 == 0.0 && (coords == Coords::Polar || coords == Coords::Corner))
        k.u1 = 0.0;  // the pole: one point for every angle
      return k;
    }

    Values value_at(const Key& k) const {
      const Patch& patch = t.patches_[static_cast<std::size_t>(k.patch)];
      if (patch.coords == Coords::Far && k.u0 == 0.0) return t.far_limit(k.u1);
      double cx = 0.0, cy = 0.0;
      t.centre(patch, k.u0, k.u1, cx, cy);
      const bool by_strips = t.kind_ == SpotKind::Rect && t.law_.kind != PressureKind::Ring;
      const SpotIntegrals v = t.kind_ == SpotKind::Map ? map_strips(cx, cy)
                              : by_strips              ? strips(cx, cy)
                              : layers                 ? (*layers)(cx, cy)
                              : confocal               ? (*confocal)(cx, cy)
                                                       : integrate(cx, cy);
      return v.channels();
    }

    // Computes every point the cells still lack (and their check points), in parallel.
    void evaluate_points(std::vector<Cell>& cells) {
      std::vector<Key> jobs;
      std::unordered_map<Key, std::size_t, KeyHash> queued;
      // Beyond the budget as soon as the round's points are more than it has left: a map of
      // 64 x 64 cells asks 400,000 in its first round, whose queue alone took 0.5 s of a pass
      // over 2,000 rows that then integrated them.
      const std::size_t left = max_points - std::min(max_points, t.stats_.points);
      auto want = [&](const Key& k) {
        if (known.count(k) == 0 && queued.emplace(k, jobs.size()).second) {
          jobs.push_back(k);
          if (jobs.size() > left) throw SpotTableOverBudget();
        }
      };
      for (Cell& c : cells) {
        for (int i1 = 0; i1 <= c.n1; ++i1)
          for (int i0 = 0; i0 <= c.n0; ++i0)
            if (!c.known[static_cast<std::size_t>(i1 * (c.n0 + 1) + i0)])
              want(key_of(c, node(i0, c.n0), node(i1, c.n1)));
        if (!c.check_known) want(key_of(c, kCheckX, kCheckY));
      }
      std::vector<Values> values(jobs.size());
      std::atomic<bool> stopped{false};
      parallel(jobs.size(), [&](std::size_t i) {
        if (stopped.load(std::memory_order_relaxed)) return;
        if (stop && stop()) {
          stopped = true;
          return;
        }
        values[i] = value_at(jobs[i]);
      });
      if (stopped) throw SpotTableBuildStopped();
      t.stats_.points += jobs.size();
      for (std::size_t i = 0; i < jobs.size(); ++i) known.emplace(jobs[i], values[i]);
      // A point is shared by the cells around it; on a map each cell holds it less its own
      // near cells (in parallel: ~1 us a point).
      parallel(cells.size(), [&](std::size_t index) {
        Cell& c = cells[index];
        for (int i1 = 0; i1 <= c.n1; ++i1)
          for (int i0 = 0; i0 <= c.n0; ++i0) {
            const std::size_t k = static_cast<std::size_t>(i1 * (c.n0 + 1) + i0);
            if (!c.known[k]) c.values[k] = held(c, key_of(c, node(i0, c.n0), node(i1, c.n1)));
            c.known[k] = 1;
          }
        if (!c.check_known) c.check = held(c, key_of(c, kCheckX, kCheckY));
        c.check_known = true;
      });
    }

    // The value cell c holds at point k: the integrals, less on a map those of its near cells.
    Values held(const Cell& c, const Key& k) const {
      Values v = known.at(k);
      if (t.near_nodes_.empty() || t.near_nodes_[static_cast<std::size_t>(c.root)].empty())
        return v;
      double cx = 0.0, cy = 0.0;
      t.centre(t.patches_[static_cast<std::size_t>(k.patch)], k.u0, k.u1, cx, cy);
      double near[kChannels] = {};
      t.add_near(c.root, cx, cy, near);
      for (std::size_t j = 0; j < kChannels; ++j) v[j] -= near[j];
      return v;
    }

    // The largest coefficient of every degree along one direction, relative to A0.
    std::vector<double> profile(const Series& s, int dir) const {
      std::vector<double> m(static_cast<std::size_t>((dir == 0 ? s.n0 : s.n1) + 1), 0.0);
      for (int l = 0; l <= s.n1; ++l)
        for (int k = 0; k <= s.n0; ++k)
          for (std::size_t ch = 0; ch < kChannels; ++ch) {
            double& slot = m[static_cast<std::size_t>(dir == 0 ? k : l)];
            slot = std::max(slot, std::fabs(s.at(k, l)[ch]) / t.scale_);
          }
      return m;
    }

    // The last coefficients along one direction and their rate of decay over the upper half.
    static std::pair<double, double> tail_and_rate(const std::vector<double>& m) {
      const std::size_t n = m.size() - 1;
      const double tail = std::max(m[n], m[n - 1]);
      const double top = std::max(m[n / 2], m[n / 2 + 1]);
      const double rate = std::pow(std::max(tail, 1e-300) / std::max(top, 1e-300),
                                   1.0 / (0.5 * static_cast<double>(n) - 1.0));
      return {tail, rate};
    }

    // The interpolation error along one direction: the last coefficients summed over a tail that
    // decays geometrically at that rate.
    static double error_estimate(const std::vector<double>& m) {
      const auto [tail, rate] = tail_and_rate(m);
      const double r = std::min(kMaxRate, rate);
      return tail * std::max(1.0, 2.0 * r / (1.0 - r));
    }

    // The next degree: a multiple of n (so that the points nest) where the coefficients,
    // extrapolated at that rate, fall below the tolerance.
    static int next_degree(const std::vector<double>& m, int n) {
      const auto [tail, rate] = tail_and_rate(m);
      const double more =
          rate < 0.95 ? std::log(tail / kSampleTolerance) / -std::log(rate) : HUGE_VAL;
      const double want = (n + more) * kSafety + 1.0;
      int next = 2 * n;
      while (next < want && next + n <= kMaxSampleDegree) next += n;
      return next;
    }
    static bool can_grow(int n) { return 2 * n <= kMaxSampleDegree; }

    void decide(Cell& c, std::vector<Cell>& next) {
      const Series s = transform(c.values, c.n0, c.n1);
      const int n0 = c.n0, n1 = c.n1;
      const std::vector<double> m0 = profile(s, 0), m1 = profile(s, 1);
      const double e0 = error_estimate(m0), e1 = error_estimate(m1);
      const Values at = sum(s, kCheckX, kCheckY);
      double miss = 0.0;
      for (std::size_t ch = 0; ch < kChannels; ++ch)
        miss = std::max(miss, std::fabs(at[ch] - c.check[ch]) / t.scale_);
      bool bad0 = e0 > kSampleTolerance, bad1 = e1 > kSampleTolerance;
      if (!bad0 && !bad1 && miss > kCheckTolerance) {
        bad0 = n0 >= n1;
        bad1 = n1 >= n0;
      }
      if ((!bad0 && !bad1) || c.depth >= kMaxDepth) {
        t.stats_.estimate = std::max(t.stats_.estimate, std::max({e0, e1, miss}));
        t.store_cell(c, s);
        return;
      }
      // (A degree grows to a multiple of itself, so that the points nest, or the cell splits.)
      if ((bad0 && can_grow(n0)) || (bad1 && can_grow(n1))) {
        Cell d = c;
        d.n0 = bad0 && can_grow(n0) ? next_degree(m0, n0) : n0;
        d.n1 = bad1 && can_grow(n1) ? next_degree(m1, n1) : n1;
        resize(d);
        const int f0 = d.n0 / n0, f1 = d.n1 / n1;
        for (int j = 0; j <= n1; ++j)
          for (int i = 0; i <= n0; ++i) {
            const std::size_t k = static_cast<std::size_t>(j * f1 * (d.n0 + 1) + i * f0);
            d.values[k] = c.values[static_cast<std::size_t>(j * (n0 + 1) + i)];
            d.known[k] = 1;
          }
        next.push_back(std::move(d));
        return;
      }
      for (Cell& p : t.split(c, bad0, bad1)) {
        p.depth = c.depth + 1;
        p.check_known = false;
        if (bad0) p.n0 = 2 * t.start_degree();
        if (bad1) p.n1 = 2 * t.start_degree();
        resize(p);
        next.push_back(std::move(p));
      }
    }
  };

  // Halves a box in its tree along the marked directions; the parts keep everything else.
  std::vector<Cell> split(const Cell& c, bool s0, bool s1) {
    std::vector<Cell> parts = {c};
    parts[0].values.clear();
    parts[0].known.clear();
    for (int dir = 0; dir < 2; ++dir) {
      if (!(dir == 0 ? s0 : s1)) continue;
      std::vector<Cell> out;
      for (Cell& p : parts) {
        const double a = dir == 0 ? p.a0 : p.a1, b = dir == 0 ? p.b0 : p.b1;
        const double mid = 0.5 * (a + b);
        TreeNode& n = tree_[static_cast<std::size_t>(p.tree)];
        n.dir = dir;
        n.mid = mid;
        for (int side = 0; side < 2; ++side) {
          Cell h = p;
          (dir == 0 ? h.a0 : h.a1) = side == 0 ? a : mid;
          (dir == 0 ? h.b0 : h.b1) = side == 0 ? mid : b;
          h.tree = static_cast<int>(tree_.size());
          tree_[static_cast<std::size_t>(p.tree)].child[side] = h.tree;
          tree_.push_back(TreeNode{});
          out.push_back(std::move(h));
        }
      }
      parts = std::move(out);
    }
    return parts;
  }

  // Stores a sampled box as pieces of degree <= kStoreDegree: its series re-expanded exactly on
  // halves (no new samples) until the coefficients beyond that degree sum to less than half
  // kStoreTolerance in every channel.
  void store_cell(const Cell& c, const Series& s) {
    struct Part {
      double x0, x1, y0, y1;  // in the cell's local coordinates
      int tree;
    };
    std::vector<Part> stack = {{-1.0, 1.0, -1.0, 1.0, c.tree}};
    while (!stack.empty()) {
      const Part p = stack.back();
      stack.pop_back();
      const bool whole = p.x0 == -1.0 && p.x1 == 1.0 && p.y0 == -1.0 && p.y1 == 1.0;
      const Series r = whole ? s : transform(resample(s, p.x0, p.x1, p.y0, p.y1), s.n0, s.n1);
      double drop0 = 0.0, drop1 = 0.0;
      for (std::size_t ch = 0; ch < kChannels; ++ch) {
        double d0 = 0.0, d1 = 0.0;
        for (int l = 0; l <= r.n1; ++l)
          for (int k = 0; k <= r.n0; ++k) {
            if (k > kStoreDegree)
              d0 += std::fabs(r.at(k, l)[ch]);
            else if (l > kStoreDegree)
              d1 += std::fabs(r.at(k, l)[ch]);
          }
        drop0 = std::max(drop0, d0 / scale_);
        drop1 = std::max(drop1, d1 / scale_);
      }
      const bool cut0 = drop0 > 0.25 * kStoreTolerance, cut1 = drop1 > 0.25 * kStoreTolerance;
      if (!cut0 && !cut1) {
        store(c, p.x0, p.x1, p.y0, p.y1, p.tree, r);
        continue;
      }
      Cell box = c;
      box.a0 = lerp(c.a0, c.b0, p.x0);
      box.b0 = lerp(c.a0, c.b0, p.x1);
      box.a1 = lerp(c.a1, c.b1, p.y0);
      box.b1 = lerp(c.a1, c.b1, p.y1);
      box.tree = p.tree;
      const std::vector<Cell> halves = split(box, cut0, cut1);
      const double xm = 0.5 * (p.x0 + p.x1), ym = 0.5 * (p.y0 + p.y1);
      std::size_t h = 0;
      for (int k = 0; k < (cut0 ? 2 : 1); ++k)
        for (int i = 0; i < (cut1 ? 2 : 1); ++i, ++h) {
          Part q{p.x0, p.x1, p.y0, p.y1, halves[h].tree};
          if (cut0) (k == 0 ? q.x1 : q.x0) = xm;
          if (cut1) (i == 0 ? q.y1 : q.y0) = ym;
          stack.push_back(q);
        }
    }
  }

  // One piece: the series cut to kStoreDegree, and per row the coefficients beyond the last one
  // that matters dropped while what is dropped sums to less than half kStoreTolerance.
  void store(const Cell& c, double x0, double x1, double y0, double y1, int tree, const Series& r) {
    Leaf leaf{lerp(c.a0, c.b0, x0),
              lerp(c.a0, c.b0, x1),
              lerp(c.a1, c.b1, y0),
              lerp(c.a1, c.b1, y1),
              0,
              0,
              coeff_.size(),
              {}};
    const int n0 = std::min(r.n0, kStoreDegree), n1 = std::min(r.n1, kStoreDegree);
    double floor = 0.5 * kStoreTolerance * scale_;
    std::vector<int> len;
    for (;;) {
      len.assign(static_cast<std::size_t>(n1 + 1), 0);
      double dropped[kChannels] = {};
      for (int l = 0; l <= n1; ++l)
        for (int k = n0; k >= 0; --k) {
          bool keep = false;
          for (std::size_t ch = 0; ch < kChannels; ++ch)
            keep = keep || std::fabs(r.at(k, l)[ch]) > floor;
          if (keep) {
            len[static_cast<std::size_t>(l)] = k + 1;
            break;
          }
          for (std::size_t ch = 0; ch < kChannels; ++ch) dropped[ch] += std::fabs(r.at(k, l)[ch]);
        }
      if (*std::max_element(dropped, dropped + kChannels) <= 0.5 * kStoreTolerance * scale_) break;
      floor *= 0.25;
    }
    int rows = 1;
    for (int l = 0; l <= n1; ++l)
      if (len[static_cast<std::size_t>(l)] > 0) rows = l + 1;
    len.resize(static_cast<std::size_t>(rows));
    len[0] = std::max(len[0], 1);
    leaf.n1 = rows - 1;
    leaf.n0 = *std::max_element(len.begin(), len.end()) - 1;
    leaf.row_len = len;
    for (int l = 0; l < rows; ++l)
      for (int k = 0; k < len[static_cast<std::size_t>(l)]; ++k)
        for (std::size_t ch = 0; ch < kChannels; ++ch) coeff_.push_back(r.at(k, l)[ch]);
    tree_[static_cast<std::size_t>(tree)].leaf = static_cast<int>(leaves_.size());
    leaves_.push_back(std::move(leaf));
  }

  bool polar_ = false;  // no confocal patch: a table law's layers read this table
  SpotKind kind_;
  PressureLaw<double> law_;
  double q_;
  std::shared_ptr<const PressureMap> map_;  // a map's table: its map
  double A0_ = 1.0, Ax_ = 0.0, Ay_ = 0.0, Axx_ = 0.0, Axy_ = 0.0, Ayy_ = 0.0;
  double scale_ = 1.0;     // the unit of the tolerances: A0, or less (see the private constructor)
  double near_ = 0.0;      // the polar patch's radius P_near, or the box's side R_near
  bool confocal_ = false;  // an elongated ellipse: the confocal patch outside the rim
  double focal_ = 0.0, mu_far_ = 0.0;  // its foci (+-focal_, 0) and outer bound
  std::vector<Patch> patches_;         // ellipse: polar, far; rectangle: box, far, corners
  std::vector<Root> roots_;
  // A map's table: for each root cell, the corner nodes of the grid cells that touch it, whose
  // integrals it holds apart (none for the far patch's cells, make_near_nodes).
  std::vector<std::vector<MapCornerNode>> near_nodes_;
  std::vector<TreeNode> tree_;
  std::vector<Leaf> leaves_;
  std::vector<double> coeff_;
  Stats stats_;
  // An annulus on an ellipse: the uniform ellipse's table, B and B^(2+d) per channel.
  std::shared_ptr<const SpotIntegralTable> uniform_;
  double inner_ = 1.0;
  std::array<double, kChannels> inner_weight_{};
};

}  // namespace frictionid::model
