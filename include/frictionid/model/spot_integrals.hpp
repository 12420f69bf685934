// The friction integrals of any contact spot about the instantaneous centre of rotation
// (docs/physics.md §9.3). With the centre of rotation c = (-v_y, v_x)/(omega R) (units of R),
// the slip direction at a point r is s e3 x (r - c)/|r - c| (s = sign of omega): it depends only
// on the angle phi of r - c. In polar coordinates (r, phi) about c the integrand is therefore
// smooth along every ray, and the only non-smooth places are where a ray meets the spot's rim,
// a step or kink of the pressure, or a corner: the radial integrals split there, and the angular
// integral splits at the directions of corners and the tangents to rims and steps.
//
// For the ellipse and the rectangle the polar coordinates are taken in the reference frame
// (X, Y) = (x, y/q), where the spot is the unit disk or the square [-1, 1]^2: a ray there is a ray
// in the physical plane too (a linear map keeps lines), with physical direction (cos phi, q sin
// phi) and area element q r dr dphi.
//
// Everything here is plain double: the integrals depend on the kinematics, the spot and the
// pressure shape only, never on f, kappa, h or h_y (spot_model.hpp combines them).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <vector>

#include <frictionid/model/contact_spot.hpp>
#include <frictionid/model/ellipse_nearest_point.hpp>
#include <frictionid/model/gauss_legendre_rule.hpp>
#include <frictionid/model/pressure_law.hpp>
#include <frictionid/model/tanh_sinh_rule.hpp>

namespace frictionid::model {

// Twelve values in the order ex[0..2], ey[0..2], x_ey[0..2], y_ex[0..2] (the channels of the
// strip integrators' accumulators and of the table) into any struct with those four triples:
// SpotIntegrals, or the model's SpotIntegralsT of a dual number.
template <typename Integrals, typename V>
Integrals integrals_from_channels(const V* v) {
  Integrals out;
  for (std::size_t w = 0; w < 3; ++w) {
    out.ex[w] = v[w];
    out.ey[w] = v[3 + w];
    out.x_ey[w] = v[6 + w];
    out.y_ex[w] = v[9 + w];
  }
  return out;
}

// With e = e3 x (r - c)/|r - c| = (-(y - c_y), x - c_x)/|r - c| and the weights
// w = sigma0 * {1, x, y} (index 0, 1, 2):
//   ex[w] = ∫ w e_x dA, ey[w] = ∫ w e_y dA, x_ey[w] = ∫ w x e_y dA, y_ex[w] = ∫ w y e_x dA,
// in units of R^2 (ex, ey) and R^3 (x_ey, y_ex) times the pressure's own scale.
struct SpotIntegrals {
  std::array<double, 3> ex{}, ey{}, x_ey{}, y_ex{};

  // The degree of each channel's weight in x and y (ex[w], ey[w]: 1, x, y; x_ey[w] and y_ex[w]
  // one more): the uniform ellipse scaled by s carries s^(2 + degree) times the unit one's
  // integrals at c/s (docs/physics.md (9.8)).
  static constexpr int kChannelDegree[12] = {0, 1, 1, 0, 1, 1, 1, 2, 2, 1, 2, 2};
  // s^(2 + degree) per channel.
  static std::array<double, 12> scale_weights(double s) {
    std::array<double, 12> w{};
    for (std::size_t j = 0; j < 12; ++j) w[j] = std::pow(s, 2 + kChannelDegree[j]);
    return w;
  }

  // From twelve channels in the order of integrals_from_channels.
  static SpotIntegrals from_channels(const double* v) {
    return integrals_from_channels<SpotIntegrals>(v);
  }

  // The twelve values in that order (from_channels' inverse).
  std::array<double, 12> channels() const {
    std::array<double, 12> v{};
    for (std::size_t w = 0; w < 3; ++w) {
      v[w] = ex[w];
      v[3 + w] = ey[w];
      v[6 + w] = x_ey[w];
      v[9 + w] = y_ex[w];
    }
    return v;
  }

  SpotIntegrals& operator+=(const SpotIntegrals& o) {
    for (int w = 0; w < 3; ++w) {
      ex[w] += o.ex[w];
      ey[w] += o.ey[w];
      x_ey[w] += o.x_ey[w];
      y_ex[w] += o.y_ex[w];
    }
    return *this;
  }
  SpotIntegrals operator-(const SpotIntegrals& o) const {
    SpotIntegrals r = *this;
    for (int w = 0; w < 3; ++w) {
      r.ex[w] -= o.ex[w];
      r.ey[w] -= o.ey[w];
      r.x_ey[w] -= o.x_ey[w];
      r.y_ex[w] -= o.y_ex[w];
    }
    return r;
  }
  SpotIntegrals operator*(double s) const {
    SpotIntegrals r = *this;
    for (int w = 0; w < 3; ++w) {
      r.ex[w] *= s;
      r.ey[w] *= s;
      r.x_ey[w] *= s;
      r.y_ex[w] *= s;
    }
    return r;
  }
};

// The integrals at |c| -> inf in direction gamma: the slip direction is e = (sin gamma,
// -cos gamma) over the whole spot, so each is a moment of sigma0 times a component of e
// (docs/physics.md §9.3; a map's first moments and Axy need not vanish).
inline SpotIntegrals sliding_limit_integrals(const SpotMoments<double>& m, double gamma) {
  const double s = std::sin(gamma), c = std::cos(gamma);
  const double v[12] = {s * m.A0,  s * m.Ax,   s * m.Ay,   -c * m.A0, -c * m.Ax, -c * m.Ay,
                        -c * m.Ax, -c * m.Axx, -c * m.Axy, s * m.Ay,  s * m.Axy, s * m.Ayy};
  return SpotIntegrals::from_channels(v);
}

// The rules of the two nested integrals. The defaults (tanh-sinh, step 1/8) keep the integrals
// within ~1e-11 of the spot's scale; fine_rule() in both reaches ~1e-14 at ~5x the cost.
struct SpotRules {
  const std::vector<QuadratureNode>* radial = &radial_rule();
  const std::vector<QuadratureNode>* angular = &radial_rule();
  bool fine_maps = false;  // the angular rule on a map's narrow pieces too (a reference)
  // An ellipse's rays under the power laws (1 - rho^2)^n (uniform, Hertz, parabolic, power:n)
  // in closed form (SpotIntegrator::power_ray) instead of the radial rule, and with the default
  // angular rule their directions by Gauss–Legendre sized by the integrand's singular
  // directions; false keeps the rules (a reference).
  bool closed_rays = true;
};

class SpotIntegrator {
 public:
  // law is ignored for a map. q is the aspect of an ellipse or a rectangle (1 otherwise).
  SpotIntegrator(const ContactSpot& spot, const PressureLaw<double>& law, double q,
                 SpotRules rules = {})
      : kind_(spot.kind == SpotKind::Circle ? SpotKind::Ellipse : spot.kind),
        law_(law),
        q_(spot.has_aspect() ? q : 1.0),
        map_(spot.map),
        rules_(rules) {
    if (kind_ != SpotKind::Map) {
      // Every breakpoint cuts the rays and the angular range (rays tangent to its line) up to
      // kMaxBreaks; a fine table's thousands of kinks are left to the rules, its steps never.
      // The model takes a table law on an ellipse by layers of the uniform ellipse instead
      // (spot_point_integrator.hpp), exact for any number of samples and 100 times faster.
      // A table's interpolant is a cubic in rho between two samples: 16 Gauss–Legendre points
      // take such a piece of a ray, and a narrow angular piece between two tangents (endpoint
      // singularities like t^(3/2)) takes 20 after a sine-squared substitution, within 3e-12 of
      // f N for 21 to 65 samples, where the default rules made a point cost ~0.3 s for 41.
      std::vector<double> kept = law_.breakpoints();
      // Only with the default rules: a caller that asks for others (a reference) gets them.
      cubic_pieces_ = law_.kind == PressureKind::Table && kept.size() <= kMaxBreaks &&
                      rules_.radial == &radial_rule() && rules_.angular == &radial_rule();
      if (kept.size() > kMaxBreaks) kept = law_.steps();
      for (double b : kept)
        if (b > 0.0 && b < 1.0) breaks_.push_back(b);
      // sigma0 = (1 - rho^2)^n with 2n whole: uniform, parabolic, Hertz and power:n.
      if (law_.kind == PressureKind::Uniform) twice_power_ = 0;
      if (law_.kind == PressureKind::Hertz) twice_power_ = 1;
      if (law_.kind == PressureKind::Parabolic) twice_power_ = 2;
      const double twice = 2.0 * law_.n;
      if (law_.kind == PressureKind::Power && twice >= 0.0 && twice <= kMaxTwicePower &&
          twice == std::floor(twice))
        twice_power_ = static_cast<int>(twice);
      if (law_.kind == PressureKind::Power && twice_power_ < 0) {
        any_power_ = true;  // power:n, any other n: the incomplete beta function by series
        const double n = law_.n;
        full_[0] = std::exp(std::lgamma(0.5) + std::lgamma(n + 1.0) - std::lgamma(n + 1.5));
        full_[1] = 0.0;
        for (int k = 2; k < 4; ++k) full_[k] = (k - 1) * full_[k - 2] / (2.0 * n + k + 1.0);
      }
      // (1 - rho^2)^n grows like |1 - d^2|^n off the real axis, and with it the error bound.
      if (twice_power_ >= 0 || any_power_)
        angular_log_ += kAngularLogPerPower * (any_power_ ? law_.n : 0.5 * twice_power_);
      if (!rules_.closed_rays || !breaks_.empty() || kind_ != SpotKind::Ellipse) {
        twice_power_ = -1;
        any_power_ = false;
      }
    }
  }

  static constexpr std::size_t kMaxBreaks = 64;

  double q() const { return q_; }

  // The integrals for the centre of rotation at physical (cx, cy), units of R.
  SpotIntegrals operator()(double cx, double cy) const {
    if (law_.kind == PressureKind::Ring && kind_ != SpotKind::Map) return rim_integrals(cx, cy);
    const double CX = cx, CY = cy / q_;  // reference coordinates of the centre
    SpotIntegrals out;
    // On an ellipse under a power law the angular integrand's singularities are known: from
    // outside (for 2n whole, cone) and from inside, Gauss–Legendre sized by their distance, with
    // the default rules.
    const double P = std::hypot(CX, CY);
    const bool power_law = (twice_power_ >= 0 || any_power_) && rules_.angular == &radial_rule();
    if (power_law && twice_power_ >= 0 && P > 1.0) {
      cone(CX, CY, P, std::atan2(CY, CX), out);
      return out;
    }
    std::vector<double> cuts;
    angular_pieces(CX, CY, cuts);
    Ray ray;
    const bool gauss = power_law && P < 1.0;
    std::vector<std::complex<double>> singular;
    if (gauss) singular = singular_directions(P, std::atan2(CY, CX), cuts.front());
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const double a = cuts[k], b = cuts[k + 1], len = b - a;
      if (!(len > 0.0)) continue;
      if (gauss) {
        halve(a, b, singular, 0, [&](double from, double length, int points) {
          for (const auto& node : gauss_legendre_rule(points)) {
            const double phi = from + length * node.from_left;
            const double c = std::cos(phi), s = std::sin(phi);
            accumulate(out, node.weight * length, c, s, ray_moments(CX, CY, c, s, ray));
          }
        });
        continue;
      }
      if (kind_ == SpotKind::Map && len < kNarrowPiece && !rules_.fine_maps) {
        map_piece(CX, CY, a, b, ray, out);
        continue;
      }
      const bool narrow = cubic_pieces_ && kind_ == SpotKind::Ellipse && len < kNarrowTablePiece;
      for (const auto& node : narrow ? sine_squared_angular_rule() : *rules_.angular) {
        const double phi = a + len * node.from_left;
        const double c = std::cos(phi), s = std::sin(phi);
        const std::array<double, 6> m = ray_moments(CX, CY, c, s, ray);
        accumulate(out, node.weight * len, c, s, m);
      }
    }
    return out;
  }

 private:
  static constexpr double kNarrowTablePiece = 0.25;
  static const std::vector<QuadratureNode>& sine_squared_angular_rule() {
    static const std::vector<QuadratureNode> rule = make_sine_squared_rule(20);
    return rule;
  }
  struct Ray {
    std::vector<double> cuts;  // radial split points, ascending
  };

  // A map's pieces between the directions of its grid nodes are many and narrow, and the
  // integrand is analytic on each, but the distance at which a ray crosses a grid line, d/sin,
  // has its pole in the direction along the line: an axis direction, where a line passing
  // close to the centre of rotation puts it next to narrow pieces. Cut each piece geometrically
  // towards the nearest axis until every part is at least its own width away from it; 16 Gauss
  // points then converge like 5.8^-32, at a third of the tanh-sinh rule's cost.
  void map_piece(double CX, double CY, double a, double b, Ray& ray, SpotIntegrals& out) const {
    const double mid = 0.5 * (a + b);
    const double axis = std::round(mid / (0.5 * M_PI)) * (0.5 * M_PI);
    auto integrate = [&](double from, double to) {
      const double len = to - from;
      for (const auto& node : narrow_piece_rule()) {
        const double phi = from + len * node.from_left;
        const double c = std::cos(phi), s = std::sin(phi);
        accumulate(out, node.weight * len, c, s, ray_moments(CX, CY, c, s, ray));
      }
    };
    if (axis == a || axis == b) {
      // A piece that starts on an axis sees no line along it: a parallel line is crossed only
      // beyond the direction of its nearest node, which is a cut.
      integrate(a, b);
    } else if (axis < a) {  // grade upwards from a
      double from = a;
      while (from < b) {
        const double to = std::min(b, axis + 2.0 * (from - axis));
        integrate(from, to);
        from = to;
      }
    } else if (axis > b) {  // grade downwards from b
      double to = b;
      while (to > a) {
        const double from = std::max(a, axis - 2.0 * (axis - to));
        integrate(from, to);
        to = from;
      }
    } else {
      integrate(a, b);  // an axis inside: it is one of the cuts, so this does not happen
    }
  }

  // The complex directions where the angular integrand of a centre inside the ellipse is
  // singular, each repeating every half turn, over the turn from `lo` and half a turn beyond
  // either end: the chord's half-length h = sqrt(1 - d^2) vanishes at beta + pi/2 +-
  // i acosh(1/P) (d = P sin(phi - beta); the closed forms' other branch points, atan2(w0, u0)
  // and the powers of 1 - u0^2, sit there too), and the physical direction's length
  // sqrt(cos^2 + q^2 sin^2) at the squeezed axis +- i atanh(min(q, 1/q)). (Imaginary parts as
  // distances: the pairs are symmetric.)
  std::vector<std::complex<double>> singular_directions(double P, double beta, double lo) const {
    std::vector<std::complex<double>> out;
    auto repeat = [&](double re, double im) {
      const double k0 = std::floor((lo - re) / M_PI);
      for (double k = k0 - 1.0; k <= k0 + 4.0; k += 1.0) out.push_back({re + k * M_PI, im});
    };
    if (P > 0.0) repeat(beta + 0.5 * M_PI, std::acosh(1.0 / P));
    if (q_ != 1.0) repeat(q_ < 1.0 ? 0.5 * M_PI : 0.0, std::atanh(std::min(q_, 1.0 / q_)));
    return out;
  }

  // [a, b] halved until every singular point keeps kZ half-lengths from its middle (a centre
  // next to the rim brings the chord's pair within acosh(1/P) ~ sqrt(2(1 - P)) of a cut, so the
  // halving crowds there geometrically), then rule(from, length, points) with the Gauss–Legendre
  // points the nearest one's Bernstein ellipse asks for 1e-14 (more for a higher power n, whose
  // (1 - rho^2)^n grows off the real axis): 85-230 directions a point for aspects 0.05-4, where
  // tanh-sinh on every piece took 300-900. The weights and the direction are trigonometric
  // polynomials of degree <= 4, which grow like exp(4 |Im phi|) off the real axis: as if
  // singular kGrowthDistance above every point too.
  template <typename Rule>
  void halve(double a, double b, const std::vector<std::complex<double>>& singular, int depth,
             const Rule& rule) const {
    const double h = 0.5 * (b - a), mid = a + h;
    double rho = bernstein_parameter_through(0.0, kGrowthDistance / h);
    for (const std::complex<double>& z : singular)
      rho = std::min(rho, bernstein_parameter_through((z.real() - mid) / h, z.imag() / h));
    if (rho < kAngularRho && depth < kMaxAngularDepth) {
      halve(a, mid, singular, depth + 1, rule);
      halve(mid, b, singular, depth + 1, rule);
      return;
    }
    const double n = std::ceil(gauss_legendre_points(rho, angular_log_, 0));
    rule(a, b - a, static_cast<int>(std::clamp(n, 3.0, 32.0)));
  }

  // From outside the ellipse under (1 - rho^2)^n with 2n whole: the visible cone in the angle
  // theta of d = sin(theta) (d the ray's distance from the centre), theta in [-pi/2, pi/2]:
  // phi = beta + pi - asin(sin(theta)/P), h = cos(theta) and b = -sqrt(P^2 - sin^2 theta)
  // exactly, dphi = -cos(theta) dtheta/sqrt(P^2 - sin^2 theta). The moments are h^(2n+1) times
  // a polynomial in h^2 (the odd powers of t integrate to 0 over the whole chord), so the
  // integrand is h^(2n+2)/sqrt(P^2 - sin^2 theta) times analytic: analytic at the tangent rays
  // theta = +-pi/2, where in phi it had a branch point (phi - phi_t)^(n+1/2). Its singular
  // directions: sqrt(P^2 - sin^2 theta) = 0 at +-pi/2 +- i acosh(P), and the squeezed axis's
  // pair mapped by theta = asin(P sin(phi - beta)). Halved and integrated as from inside.
  void cone(double CX, double CY, double P, double beta, SpotIntegrals& out) const {
    std::vector<std::complex<double>> sing;
    const double ac = std::acosh(P);
    for (double re : {-1.5 * M_PI, -0.5 * M_PI, 0.5 * M_PI, 1.5 * M_PI}) sing.push_back({re, ac});
    if (q_ != 1.0) {
      const double axis = q_ < 1.0 ? 0.5 * M_PI : 0.0, tau = std::atanh(std::min(q_, 1.0 / q_));
      const double k0 = std::round((beta + M_PI - axis) / M_PI);
      for (double k = k0 - 1.0; k <= k0 + 1.0; k += 1.0) {
        const std::complex<double> phi(axis + k * M_PI, tau);
        const std::complex<double> th = std::asin(P * std::sin(phi - beta));
        sing.push_back({th.real(), std::fabs(th.imag())});
      }
    }
    halve(-0.5 * M_PI, 0.5 * M_PI, sing, 0, [&](double a, double len, int points) {
      const double b = a + len;
      for (const auto& node : gauss_legendre_rule(points)) {
        // cos(theta) to full precision next to either end.
        const double theta = a + len * node.from_left;
        const double ch = a == -0.5 * M_PI && node.from_left < 0.5 ? std::sin(len * node.from_left)
                          : b == 0.5 * M_PI && node.from_right < 0.5
                              ? std::sin(len * node.from_right)
                              : std::cos(theta);
        const double d = std::sin(theta), root = std::sqrt((P - d) * (P + d));
        const double phi = beta + M_PI - std::asin(d / P);
        const double c = std::cos(phi), s = std::sin(phi);
        std::array<double, 6> m{};
        power_ray(CX, CY, c, s, -root, d, ch, root - ch, m);
        accumulate(out, node.weight * len * ch / root, c, s, m);
      }
    });
  }

  static constexpr double kAngularLog = 32.0;  // -ln of a piece's relative error (n = 0)
  static constexpr double kAngularLogPerPower = 4.0;
  static constexpr double kAngularRho = 2.13;  // Bernstein parameter at 1.3 half-lengths
  static constexpr double kGrowthDistance = 1.0;
  static constexpr int kMaxAngularDepth = 60;

  static constexpr double kNarrowPiece = 0.2;  // radians
  static const std::vector<QuadratureNode>& narrow_piece_rule() {
    static const std::vector<QuadratureNode> rule = make_gauss_legendre_rule(16);
    return rule;
  }
  static const std::vector<QuadratureNode>& cell_rule() {
    // Along a ray inside one cell of a map, sigma0 is quadratic in r: with r dr and weights of
    // degree <= 2 the integrand has degree <= 5, which 3 Gauss points integrate exactly.
    static const std::vector<QuadratureNode> rule = make_gauss_legendre_rule(3);
    return rule;
  }

  // Adds one direction's contribution. m = ∫ sigma0 r {1, x, y, x^2, xy, y^2} dr along the ray.
  void accumulate(SpotIntegrals& out, double w, double c, double s,
                  const std::array<double, 6>& m) const {
    // Physical direction of the ray (c, q s); e = e3 x that, normalised; dA = q r dr dphi.
    const double len = std::sqrt(c * c + q_ * q_ * s * s);
    const double ex = -q_ * s / len, ey = c / len, W = w * q_;
    out.ex[0] += W * ex * m[0];
    out.ex[1] += W * ex * m[1];
    out.ex[2] += W * ex * m[2];
    out.ey[0] += W * ey * m[0];
    out.ey[1] += W * ey * m[1];
    out.ey[2] += W * ey * m[2];
    out.x_ey[0] += W * ey * m[1];
    out.x_ey[1] += W * ey * m[3];
    out.x_ey[2] += W * ey * m[4];
    out.y_ex[0] += W * ex * m[2];
    out.y_ex[1] += W * ex * m[4];
    out.y_ex[2] += W * ex * m[5];
  }

  // --- Angular pieces -------------------------------------------------------------------------

  // Cuts of the angular range about the reference centre (CX, CY): ascending angles from the
  // first to the last, covering either the full turn or, from outside the spot, the cone that
  // sees it.
  void angular_pieces(double CX, double CY, std::vector<double>& cuts) const {
    std::vector<double> marks;
    double lo = 0.0, hi = 0.0;
    bool full = true;
    switch (kind_) {
      case SpotKind::Circle:
      case SpotKind::Ellipse: {
        const double p = std::hypot(CX, CY);
        const double beta = p > 0.0 ? std::atan2(CY, CX) : 0.0;
        const double inward = beta + M_PI;
        marks = {beta, beta + 0.5 * M_PI, inward, beta - 0.5 * M_PI};
        std::vector<double> radii = breaks_;
        radii.push_back(1.0);
        for (double B : radii) {
          if (p > B) {
            const double half = std::asin(B / p);
            marks.push_back(inward - half);
            marks.push_back(inward + half);
          }
        }
        if (p > 1.0) {
          full = false;
          const double half = std::asin(1.0 / p);
          lo = inward - half;
          hi = inward + half;
        }
        break;
      }
      case SpotKind::Rect:
      case SpotKind::Map: {
        double x0 = -1, x1 = 1, y0 = -1, y1 = 1;
        std::vector<double> xs, ys;
        if (kind_ == SpotKind::Map) {
          xs = map_->x;
          ys = map_->y;
          x0 = xs.front();
          x1 = xs.back();
          y0 = ys.front();
          y1 = ys.back();
        } else {
          xs = {-1.0, 0.0, 1.0};
          for (double b : breaks_) {
            xs.push_back(b);
            xs.push_back(-b);
          }
          ys = {-1.0, 1.0};
        }
        // Corners of every cell (or of every strip of the rectangle's law).
        for (double X : xs)
          for (double Y : ys)
            if (X != CX || Y != CY) marks.push_back(std::atan2(Y - CY, X - CX));
        const bool inside = CX >= x0 && CX <= x1 && CY >= y0 && CY <= y1;
        if (!inside) {
          // The box is convex: seen from outside, its corners span less than a half turn
          // about the direction to its centre.
          full = false;
          const double mid = std::atan2(0.5 * (y0 + y1) - CY, 0.5 * (x0 + x1) - CX);
          lo = HUGE_VAL;
          hi = -HUGE_VAL;
          for (double X : {x0, x1})
            for (double Y : {y0, y1}) {
              const double d = std::remainder(std::atan2(Y - CY, X - CX) - mid, 2 * M_PI);
              lo = std::min(lo, mid + d);
              hi = std::max(hi, mid + d);
            }
        }
        break;
      }
    }
    // The physical direction (cos phi, q sin phi)/len turns fastest about the reference axis
    // that the spot's long axis squeezes: phi = +-pi/2 for q < 1, 0 and pi for q > 1, where
    // its branch points sit atanh(min(q, 1/q)) off the real line. Cut there, and grade the
    // neighbouring pieces to that scale when it is small.
    if (kind_ == SpotKind::Map)
      for (double a : {0.0, 0.5 * M_PI, M_PI, 1.5 * M_PI}) marks.push_back(a);
    const double axis = q_ < 1.0 ? 0.5 * M_PI : 0.0;
    const double scale = std::atanh(std::min(q_, 1.0 / q_));
    for (double a : {axis, axis + M_PI}) {
      marks.push_back(a);
      if (scale < 0.35)
        for (double k : {0.25, 1.0, 4.0}) {
          if (k * scale > 0.5 * M_PI) continue;
          marks.push_back(a - k * scale);
          marks.push_back(a + k * scale);
        }
    }
    if (full) {
      lo = marks.front();
      hi = lo + 2 * M_PI;
    }
    cuts.clear();
    cuts.push_back(lo);
    for (double m : marks) {
      // The mark's angle in [lo, lo + 2 pi).
      double a = lo + std::fmod(std::fmod(m - lo, 2 * M_PI) + 2 * M_PI, 2 * M_PI);
      if (a > lo && a < hi) cuts.push_back(a);
    }
    cuts.push_back(hi);
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  }

  // --- One ray --------------------------------------------------------------------------------

  // ∫ sigma0 r {1, x, y, x^2, xy, y^2} dr along the ray from (CX, CY) in reference direction
  // (c, s), x and y physical.
  std::array<double, 6> ray_moments(double CX, double CY, double c, double s, Ray& ray) const {
    std::array<double, 6> m{};
    switch (kind_) {
      case SpotKind::Circle:
      case SpotKind::Ellipse:
        ellipse_ray(CX, CY, c, s, ray, m);
        break;
      case SpotKind::Rect:
        rect_ray(CX, CY, c, s, ray, m);
        break;
      case SpotKind::Map:
        map_ray(CX, CY, c, s, ray, m);
        break;
    }
    return m;
  }

  void add_point(std::array<double, 6>& m, double w, double sigma, double r, double x,
                 double y) const {
    const double g = w * sigma * r;
    m[0] += g;
    m[1] += g * x;
    m[2] += g * y;
    m[3] += g * x * x;
    m[4] += g * x * y;
    m[5] += g * y * y;
  }

  void ellipse_ray(double CX, double CY, double c, double s, Ray& ray,
                   std::array<double, 6>& m) const {
    // |C + r e|^2 = (r + b)^2 + d^2 with b = C.e and d = C x e the ray's distance from the
    // centre; 1 - rho^2 = (r_out - r)(r - r_back), r_out/back = -b +- sqrt(1 - d^2).
    const double b = CX * c + CY * s, d = CX * s - CY * c;
    const double disc = (1.0 - d) * (1.0 + d);
    if (!(disc > 0.0)) return;
    const double root = std::sqrt(disc);
    const double r_out = -b + root, r_back = -b - root;
    if (!(r_out > 0.0)) return;
    if (twice_power_ >= 0 || any_power_) return power_ray(CX, CY, c, s, b, d, root, r_back, m);
    const double r_in = std::max(0.0, r_back);
    ray.cuts.clear();
    ray.cuts.push_back(r_in);
    // The ray's closest approach to the centre, where rho(r) turns: a law with a slope at
    // rho = 0 (a cone) has a kink there.
    if (-b > r_in && -b < r_out) ray.cuts.push_back(-b);
    for (double B : breaks_) {
      const double disc_b = (B - d) * (B + d);
      if (!(disc_b > 0.0)) continue;
      const double rb = std::sqrt(disc_b);
      for (double r : {-b - rb, -b + rb})
        if (r > r_in && r < r_out) ray.cuts.push_back(r);
    }
    ray.cuts.push_back(r_out);
    std::sort(ray.cuts.begin(), ray.cuts.end());
    for (std::size_t k = 0; k + 1 < ray.cuts.size(); ++k) {
      const double a = ray.cuts[k], e = ray.cuts[k + 1], len = e - a;
      const bool at_rim = k + 2 == ray.cuts.size(), from_back = k == 0 && r_in == r_back;
      // A cubic piece far enough from rho's branch points -b +- i d (relative to its length).
      const double off = std::max({0.0, a + b, -b - e});
      const bool cubic =
          cubic_pieces_ && !at_rim && !from_back && off * off + d * d >= 0.25 * len * len;
      for (const auto& node : cubic ? smooth_piece_rule() : *rules_.radial) {
        const double r = a + len * node.from_left;
        // Distances to both crossings of the rim along the ray, exact near them.
        const double to_out = at_rim ? len * node.from_right : r_out - r;
        const double to_back = from_back ? len * node.from_left : r - r_back;
        const double rim = std::max(0.0, to_out * to_back);  // 1 - rho^2
        const double rho = std::sqrt(std::max(0.0, 1.0 - rim));
        const double sigma = law_(rho, rim / (1.0 + rho));
        const double X = CX + r * c, Y = CY + r * s;
        add_point(m, node.weight * len, sigma, r, X, q_ * Y);
      }
    }
  }

  // The same under sigma0 = (1 - rho^2)^n (uniform, Hertz, parabolic, power:n) in closed form
  // (docs/physics.md (9.9)). With r = -b + h u (h = sqrt(1 - d^2), the chord's half-length),
  // 1 - rho^2 = h^2 (1 - u^2), and the point of the ray's line nearest the centre is d (s, -c),
  // so X, Y and r are linear in u. Every moment is h^(2n+1) ∫ (1 - u^2)^(n - N) P(u) du over
  // [u0, 1], P a polynomial of degree <= 2N + 3: u0 = -1 from outside the spot, b/h from inside
  // (the ray starts at r = 0). N = n for whole n, n - 1/2 for n + 1/2 whole, else 0. The
  // integrals of the powers of u over [u0, 1], with w0 = sqrt(1 - u0^2):
  //   whole n:  L_k = (1 - u0^(k+1))/(k+1), the difference summed as (1 - u0) sum u0^j;
  //   n + 1/2:  K_0 = (atan2(w0, u0) - u0 w0)/2,  K_1 = w0^3/3,
  //             K_k = (u0^(k-1) w0^3 + (k-1) K_(k-2))/(k+2);
  //   other n:  J_0 an incomplete beta function (incomplete_power), J_1 = W^(n+1)/(2(n+1)),
  //             J_k = (u0^(k-1) W^(n+1) + (k-1) J_(k-2))/(2n+k+1), W = w0^2
  // (by parts, from d(1 - u^2)^(n+1) = -2(n+1) u (1 - u^2)^n du).
  void power_ray(double CX, double CY, double c, double s, double b, double d, double h,
                 double r_back, std::array<double, 6>& m) const {
    constexpr int kMaxDegree = kMaxTwicePower + 3;
    double u0 = -1.0, w0 = 0.0, one_minus_u0 = 2.0;
    if (r_back < 0.0) {  // inside: 1 - u0^2 = (1 - |C|^2)/h^2, 1 - u0 = r_out/h
      u0 = b / h;
      one_minus_u0 = (h - b) / h;
      if (!(one_minus_u0 > 0.0)) return;
      w0 = std::sqrt(std::max(0.0, (1.0 - CX * CX) - CY * CY)) / h;
    }
    const int N = any_power_ ? 0 : twice_power_ / 2, top = 2 * N + 3;
    const bool half = twice_power_ % 2 == 1;
    double K[kMaxDegree + 1];
    // h^(2n+1) (N = 0 for any other n)
    double scale = any_power_ ? std::pow(h, 2.0 * law_.n + 1.0) : half ? h * h : h;
    for (int i = 0; i < N; ++i) scale *= h * h;
    if (any_power_) {
      const double n = law_.n;
      if (r_back >= 0.0) {
        for (int k = 0; k <= top; ++k) K[k] = full_[k];
      } else {
        // 1 - u0^2 = (1 - u0)(1 + u0), both from the ray: 1 + u0 = -r_back/h.
        const double one_plus_u0 = -r_back / h;
        const double W1 = std::pow(one_minus_u0 * one_plus_u0, n + 1.0);  // (1 - u0^2)^(n+1)
        K[0] = incomplete_power(u0, one_minus_u0, one_plus_u0);
        K[1] = W1 / (2.0 * (n + 1.0));
        double up = 1.0;
        for (int k = 2; k <= top; ++k) {
          up *= u0;
          K[k] = (up * W1 + (k - 1) * K[k - 2]) / (2.0 * n + k + 1.0);
        }
      }
    } else if (half) {
      const double w3 = w0 * w0 * w0;
      K[0] = 0.5 * (std::atan2(w0, u0) - u0 * w0);
      K[1] = w3 / 3.0;
      double up = 1.0;  // u0^(k-1)
      for (int k = 2; k <= top; ++k) {
        up *= u0;
        K[k] = (up * w3 + (k - 1) * K[k - 2]) / (k + 2);
      }
    } else {
      double sum = 0.0, up = 1.0;  // sum_(j<=k) u0^j, u0^k
      for (int k = 0; k <= top; ++k) {
        sum += up;
        up *= u0;
        K[k] = one_minus_u0 * sum / (k + 1);
      }
    }
    // P = (1 - u^2)^N r(u), then times 1, X, y, X^2, X y, y^2 (y physical).
    double P[kMaxDegree + 1] = {-b, h};
    int deg = 1;
    for (int i = 0; i < N; ++i) {
      for (int k = deg + 2; k >= 0; --k) P[k] = (k <= deg ? P[k] : 0.0) - (k >= 2 ? P[k - 2] : 0.0);
      deg += 2;
    }
    const double X0 = s * d, X1 = h * c, Y0 = -q_ * c * d, Y1 = q_ * h * s;
    // sum_k (P (A0 + A1 u)(B0 + B1 u))_k K_k.
    auto moment = [&](double A0, double A1, double B0, double B1) {
      double sum = 0.0;
      for (int k = 0; k <= deg; ++k)
        sum += P[k] * (A0 * B0 * K[k] + (A0 * B1 + A1 * B0) * K[k + 1] + A1 * B1 * K[k + 2]);
      return scale * sum;
    };
    m[0] += moment(1.0, 0.0, 1.0, 0.0);
    m[1] += moment(X0, X1, 1.0, 0.0);
    m[2] += moment(Y0, Y1, 1.0, 0.0);
    m[3] += moment(X0, X1, X0, X1);
    m[4] += moment(X0, X1, Y0, Y1);
    m[5] += moment(Y0, Y1, Y0, Y1);
  }

  // ∫ (1 - u^2)^n du over [u0, 1] for the law's n (an incomplete beta function), by the series
  // that converges faster: about 0, ∫_0^x = sum_j C(n, j) (-1)^j x^(2j+1)/(2j+1) (ratio x^2);
  // about 1, with t = 1 - x, ∫_x^1 = 2^n t^(n+1) sum_j C(n, j) (-1)^j (t/2)^j/(n+j+1) (ratio
  // t/2). The two ratios meet at x = 1/2, where each is 1/4: at most ~27 terms for 1e-16.
  double incomplete_power(double u0, double one_minus_u0, double one_plus_u0) const {
    const double n = law_.n, x = std::fabs(u0);
    double tail;  // ∫ over [|u0|, 1]
    if (x > 0.5) {
      const double t = u0 > 0.0 ? one_minus_u0 : one_plus_u0, r = 0.5 * t;
      double a = 1.0, p = 1.0, sum = 1.0 / (n + 1.0);
      for (int j = 0; j < kSeriesTerms; ++j) {
        a *= (j - n) / (j + 1.0);
        p *= r;
        const double term = a * p / (n + j + 2.0);
        sum += term;
        if (std::fabs(term) <= 1e-17 * std::fabs(sum)) break;
      }
      tail = std::pow(2.0, n) * std::pow(t, n + 1.0) * sum;
    } else {
      const double x2 = x * x;
      double a = 1.0, p = x, sum = x;
      for (int j = 0; j < kSeriesTerms; ++j) {
        a *= (j - n) / (j + 1.0);
        p *= x2;
        const double term = a * p / (2.0 * j + 3.0);
        sum += term;
        if (std::fabs(term) <= 1e-17 * std::fabs(sum)) break;
      }
      tail = 0.5 * full_[0] - sum;
    }
    return u0 >= 0.0 ? tail : full_[0] - tail;
  }

  // Entry and exit of the ray through the box [x0, x1] x [y0, y1]; false if it misses.
  static bool clip(double CX, double CY, double c, double s, double x0, double x1, double y0,
                   double y1, double& r_in, double& r_out) {
    r_in = 0.0;
    r_out = HUGE_VAL;
    auto slab = [&](double C, double e, double lo, double hi) {
      if (e == 0.0) return C >= lo && C <= hi;
      double t0 = (lo - C) / e, t1 = (hi - C) / e;
      if (t0 > t1) std::swap(t0, t1);
      r_in = std::max(r_in, t0);
      r_out = std::min(r_out, t1);
      return true;
    };
    if (!slab(CX, c, x0, x1) || !slab(CY, s, y0, y1)) return false;
    return r_out > r_in;
  }

  void rect_ray(double CX, double CY, double c, double s, Ray& ray,
                std::array<double, 6>& m) const {
    double r_in, r_out;
    if (!clip(CX, CY, c, s, -1.0, 1.0, -1.0, 1.0, r_in, r_out)) return;
    ray.cuts.clear();
    ray.cuts.push_back(r_in);
    if (c != 0.0) {
      std::vector<double> xs = {0.0};
      for (double B : breaks_) {
        xs.push_back(B);
        xs.push_back(-B);
      }
      for (double X : xs) {
        const double r = (X - CX) / c;
        if (r > r_in && r < r_out) ray.cuts.push_back(r);
      }
    }
    ray.cuts.push_back(r_out);
    std::sort(ray.cuts.begin(), ray.cuts.end());
    // Where a segment ends on the edges |X| = 1, 1 - |X| is |c| times the distance to that end.
    const bool exits_side = c != 0.0 && std::fabs(std::fabs(CX + r_out * c) - 1.0) < 1e-12;
    const bool enters_side =
        c != 0.0 && r_in > 0.0 && std::fabs(std::fabs(CX + r_in * c) - 1.0) < 1e-12;
    for (std::size_t k = 0; k + 1 < ray.cuts.size(); ++k) {
      const double a = ray.cuts[k], e = ray.cuts[k + 1], len = e - a;
      const bool last = k + 2 == ray.cuts.size(), first = k == 0;
      const bool cubic = cubic_pieces_ && !last && !first;
      for (const auto& node : cubic ? smooth_piece_rule() : *rules_.radial) {
        const double r = a + len * node.from_left;
        const double X = CX + r * c, Y = CY + r * s;
        const double ax = std::fabs(X);
        double omr = 1.0 - ax;
        if (last && exits_side)
          omr = std::fabs(c) * len * node.from_right;
        else if (first && enters_side)
          omr = std::fabs(c) * len * node.from_left;
        omr = std::max(0.0, omr);
        const double sigma = law_(std::min(1.0, ax), omr);
        add_point(m, node.weight * len, sigma, r, X, q_ * Y);
      }
    }
  }

  void map_ray(double CX, double CY, double c, double s, Ray& ray, std::array<double, 6>& m) const {
    const PressureMap& mp = *map_;
    double r_in, r_out;
    if (!clip(CX, CY, c, s, mp.x.front(), mp.x.back(), mp.y.front(), mp.y.back(), r_in, r_out))
      return;
    ray.cuts.clear();
    ray.cuts.push_back(r_in);
    if (c != 0.0)
      for (double X : mp.x) {
        const double r = (X - CX) / c;
        if (r > r_in && r < r_out) ray.cuts.push_back(r);
      }
    if (s != 0.0)
      for (double Y : mp.y) {
        const double r = (Y - CY) / s;
        if (r > r_in && r < r_out) ray.cuts.push_back(r);
      }
    ray.cuts.push_back(r_out);
    std::sort(ray.cuts.begin(), ray.cuts.end());
    for (std::size_t k = 0; k + 1 < ray.cuts.size(); ++k) {
      const double a = ray.cuts[k], e = ray.cuts[k + 1], len = e - a;
      if (!(len > 0.0)) continue;
      for (const auto& node : cell_rule()) {
        const double r = a + len * node.from_left;
        const double X = CX + r * c, Y = CY + r * s;
        add_point(m, node.weight * len, mp(X, Y), r, X, Y);
      }
    }
  }

  // --- The ring law: all load on the rim ------------------------------------------------------

  // sigma0 = delta(rho - 1) on the ellipse's rim (line density q dtheta in reference polar
  // coordinates), or delta(|X| - 1) on the rectangle's sides (density q dY).
  SpotIntegrals rim_integrals(double cx, double cy) const {
    SpotIntegrals out;
    auto add = [&](double w, double x, double y) {
      // (hypot, which guards against overflow that only |c| > 1e145 can cause, took a third of
      // the time.)
      const double dx = x - cx, dy = y - cy, r2 = dx * dx + dy * dy;
      const double len = r2 > 1e-290 && r2 < 1e290 ? std::sqrt(r2) : std::hypot(dx, dy);
      if (!(len > 0.0)) return;
      const double inv = 1.0 / len, ex = -dy * inv, ey = dx * inv, W = w * q_;
      const double wt[3] = {1.0, x, y};
      for (int k = 0; k < 3; ++k) {
        out.ex[k] += W * wt[k] * ex;
        out.ey[k] += W * wt[k] * ey;
        out.x_ey[k] += W * wt[k] * x * ey;
        out.y_ex[k] += W * wt[k] * y * ex;
      }
    };
    // With the cuts below, step 1/32 keeps every channel within 1e-13 of A0 against step 1/512
    // for 0.02 <= q <= 4 and c anywhere, within 1e-8 of the rim too (step 1/16: 3e-10, the area
    // rules' 1/8: 6e-7): the rim is one dimensional, so 243 nodes a piece cost little.
    static const std::vector<QuadratureNode> rim_rule = make_tanh_sinh_rule(1.0 / 32.0, 1e-30);
    const auto& rule = rules_.angular == &radial_rule() ? rim_rule : *rules_.angular;
    if (kind_ == SpotKind::Rect) {
      const double CY = std::clamp(cy / q_, -1.0, 1.0);
      for (double side : {-1.0, 1.0})
        for (auto [a, e] : {std::pair{-1.0, CY}, std::pair{CY, 1.0}}) {
          const double len = e - a;
          if (!(len > 0.0)) continue;
          for (const auto& node : rule)
            add(node.weight * len, side, q_ * (a + len * node.from_left));
        }
      return out;
    }
    // Cut where the rim passes nearest c and at that point's mirror images across both axes:
    // a centre next to the rim puts the integrand's near singularity at a cut, where tanh-sinh's
    // nodes crowd, and on an elongated ellipse the far side, 2q away, is nearly as close (it
    // left 1e-9 A0 at q = 0.1 in the middle of a half turn). Not at the reference angle of c,
    // which there can lie far from the nearest point.
    const RimPoint p = nearest_rim_point(q_, cx, cy);
    const double t0 = std::atan2(std::fabs(p.y) / q_, std::fabs(p.x));  // in [0, pi/2]
    std::vector<double> cuts = {-M_PI + t0, -t0, t0, M_PI - t0, M_PI + t0};
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    // Each piece in tau = tan((t - m)/2) about its middle m, |tau| <= tan(len/4) <= 1: cos t and
    // sin t are the rational (1 - tau^2, 2 tau)/(1 + tau^2) turned by m and dt = 2 dtau/(1 +
    // tau^2), analytic on the piece, where sincos at every node took a quarter of the time.
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const double a = cuts[k], len = cuts[k + 1] - a;
      if (!(len > 0.0)) continue;
      const double m = a + 0.5 * len, T = std::tan(0.25 * len), cm = std::cos(m), sm = std::sin(m);
      for (const auto& node : rule) {
        const double tau = T * (node.from_left - node.from_right), d = 1.0 / (1.0 + tau * tau);
        const double c = (1.0 - tau * tau) * d, s = 2.0 * tau * d;
        add(node.weight * 4.0 * T * d, cm * c - sm * s, q_ * (sm * c + cm * s));
      }
    }
    return out;
  }

  SpotKind kind_;
  PressureLaw<double> law_;
  double q_;
  std::shared_ptr<const PressureMap> map_;
  SpotRules rules_;
  std::vector<double> breaks_;  // the law's breakpoints in (0, 1)
  bool cubic_pieces_ = false;   // a table cut at every sample: a cubic between two of them
  static constexpr int kMaxTwicePower = 8;  // power:4
  int twice_power_ = -1;    // 2n of a law (1 - rho^2)^n whose rays are closed forms, or -1
  bool any_power_ = false;  // power:n with another n: closed forms but for a series
  double angular_log_ = kAngularLog;
  static constexpr int kSeriesTerms = 60;
  double full_[4] = {};  // ∫ u^k (1 - u^2)^n du over [-1, 1], k < 4 (any_power_)
};

}  // namespace frictionid::model
