// One wheel-form row into a native row (io/wheel_rows.hpp; docs/physics.md §1.1).
#include "io/wheel_rows.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

#include <frictionid/io/input_error.hpp>
#include "io/text.hpp"

namespace frictionid::io_detail {

namespace {

constexpr double kPi = 3.141592653589793;
constexpr double kHalfPi = 1.5707963267948966;  // the double nearest pi/2 (below it)
using text::kNaN;

const WheelSlotInfo kSlots[kWheelSlotCount] = {
    {"V", Quantity::Speed, "the speed of the contact centre [m/s], >= 0"},
    {"alpha", Quantity::Angle, "the slip angle [rad], between -90 and 90 deg"},
    {"slip_ratio", Quantity::Dimensionless, "the slip ratio, Omega r_e = V_x (1 + slip_ratio)"},
    {"omega_w", Quantity::AngularRate,
     "the wheel's spin about its axle [rad/s], positive rolling forward"},
    {"r_e", Quantity::Length, "the effective rolling radius [m], > 0"},
    {"gamma", Quantity::Angle, "the inclination angle [rad]"},
    {"psi_dot", Quantity::AngularRate, "the yaw rate [rad/s]"},
    {"R", Quantity::Length, "the contact radius [m], > 0"},
    {"Fz", Quantity::Force, "the normal force on the tire [N]"},
    {"Fx", Quantity::Force, "the longitudinal force on the tire [N]"},
    {"Fy", Quantity::Force, "the lateral force on the tire [N]"},
    {"Mz", Quantity::Moment, "the aligning moment on the tire [N m]"},
    {"My", Quantity::Moment, "the rolling resistance moment on the tire [N m]"},
    {"Mx", Quantity::Moment, "the overturning moment on the tire [N m]"},
};

// -0 becomes +0 (every other value is unchanged), so that rows which differ only in the sign of
// a zero (0 written in ISO axes, -0 computed from the SAE one) give the same bits.
double plus_zero(double x) {
  return x + 0.0;
}

std::string number(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", x);
  return buf;
}

}  // namespace

const WheelSlotInfo& wheel_slot(int slot) {
  return kSlots[slot];
}

int wheel_slot_index(std::string_view name) {
  for (int s = 0; s < kWheelSlotCount; ++s)
    if (name == kSlots[s].name) return s;
  return -1;
}

std::string WheelColumns::describe(int slot) const {
  const std::string& h = header[slot];
  const HeaderName split = split_header_name(h);
  if (split.name == kSlots[slot].name) return text::shown(h);
  return text::shown(h) + " (" + kSlots[slot].name + ")";
}

WheelConverter::WheelConverter(std::string path, std::size_t header_line, WheelColumns columns,
                               Axes axes, std::optional<double> contact_radius,
                               bool require_channels)
    : path_(std::move(path)),
      columns_(std::move(columns)),
      axes_(axes),
      contact_radius_(contact_radius),
      require_channels_(require_channels) {
  const WheelColumns& c = columns_;
  std::string missing;
  const auto need = [&](bool ok, const std::string& what) {
    if (!ok) missing += (missing.empty() ? "" : ", ") + what;
  };
  need(c.has(kWheelV), "V");
  need(c.has(kWheelAlpha), "alpha");
  need(c.has(kWheelSlipRatio) || c.has(kWheelOmegaW), "slip_ratio or omega_w");
  need(c.has(kWheelRe) || (c.has(kWheelSlipRatio) && c.has(kWheelOmegaW)), "r_e");
  need(c.has(kWheelGamma), "gamma");
  need(c.has(kWheelR) || contact_radius_.has_value(), "R (or --contact-radius)");
  need(c.has(kWheelFz), "Fz");
  if (!missing.empty())
    throw InputError(path_, header_line, 0,
                     "the wheel form needs the column(s) " + missing +
                         "; its columns are V, alpha, slip_ratio or omega_w, r_e, gamma, psi_dot "
                         "(optional), R, Fz, Fx, Fy, Mz, My, Mx, each optionally with a unit "
                         "in brackets such as V[km/h] (docs/design.md §4.1a)");
  if (c.has(kWheelR) && contact_radius_)
    throw InputError(path_, header_line, c.field[kWheelR],
                     "the contact radius is given twice, by the column " + c.describe(kWheelR) +
                         " and by --contact-radius; keep one of them");
  if (contact_radius_ && !(*contact_radius_ > 0.0 && std::isfinite(*contact_radius_)))
    throw InputError("--contact-radius: got " + number(*contact_radius_) +
                     "; expected a contact radius > 0 [m]");
  bool any_channel = false;
  for (int s = kFirstWheelChannel; s < kWheelSlotCount; ++s) any_channel |= c.has(s);
  if (!any_channel && require_channels_)
    throw InputError(path_, header_line, 0,
                     "no measured force or moment column; expected at least one of Fx, Fy, Mz, "
                     "My, Mx (what the road exerts on the tire)");
}

void WheelConverter::reject(std::size_t line, int slot, const std::string& what) const {
  throw InputError(path_, line, columns_.field[slot], what);
}

void WheelConverter::append(const WheelRow& row, std::size_t line, Dataset& out) const {
  const WheelColumns& c = columns_;
  const auto& v = row.value;
  const auto& given = row.given;
  const bool sae = axes_ == Axes::Sae;
  // A column the file has must have a value in every row: V, alpha, gamma, Fz, R, psi_dot, and
  // r_e where the row needs it; slip_ratio and omega_w need one of the two.
  for (int s : {kWheelV, kWheelAlpha, kWheelGamma, kWheelPsiDot, kWheelR, kWheelFz})
    if (c.has(s) && !given[s])
      reject(line, s, "empty field in column " + c.describe(s) + "; expected " + kSlots[s].meaning);
  const bool slip = given[kWheelSlipRatio];
  const bool spin = given[kWheelOmegaW];
  if (!slip && !spin)
    reject(line, c.has(kWheelSlipRatio) ? kWheelSlipRatio : kWheelOmegaW,
           "neither slip_ratio nor omega_w has a value in this row; expected one of them (the "
           "wheel's speed follows from either)");
  const bool needs_re = !(slip && spin);
  if (needs_re && !given[kWheelRe])
    reject(line, c.has(kWheelRe) ? kWheelRe : (slip ? kWheelSlipRatio : kWheelOmegaW),
           c.has(kWheelRe) ? "empty field in column " + c.describe(kWheelRe) + "; expected " +
                                 kSlots[kWheelRe].meaning
                           : std::string("this row gives only one of slip_ratio and omega_w, "
                                         "which needs the effective rolling radius r_e; add an "
                                         "r_e column"));

  const double V = v[kWheelV];
  if (!(V >= 0.0))
    reject(line, kWheelV,
           "column " + c.describe(kWheelV) + " has " + number(V) +
               " m/s; expected the speed of the contact centre, >= 0 (its direction is alpha)");
  const double alpha = v[kWheelAlpha];
  if (!(std::abs(alpha) < kHalfPi))
    reject(line, kWheelAlpha,
           "column " + c.describe(kWheelAlpha) + " has " + number(alpha * 180.0 / kPi) +
               " deg; expected a slip angle strictly between -90 and 90 deg (|alpha| >= 90 deg "
               "means the wheel does not travel forward along its heading)");
  const double Fz = v[kWheelFz];
  if (!sae && !(Fz > 0.0))
    reject(line, kWheelFz,
           "column " + c.describe(kWheelFz) + " has " + number(Fz) +
               " N; expected Fz > 0 in ISO axes (z up: the road pushes the tire up); a file in "
               "SAE axes (z down, Fz < 0) needs --axes sae");
  if (sae && !(Fz < 0.0))
    reject(line, kWheelFz,
           "column " + c.describe(kWheelFz) + " has " + number(Fz) +
               " N; expected Fz < 0 in SAE axes (z down: the road pushes the tire up, along -z); "
               "a file in ISO axes (Fz > 0) needs --axes iso");
  const double re = needs_re ? v[kWheelRe] : kNaN;
  if (needs_re && !(re > 0.0))
    reject(line, kWheelRe,
           "column " + c.describe(kWheelRe) + " has " + number(re) +
               " m; expected the effective rolling radius, > 0");
  const double R = c.has(kWheelR) ? v[kWheelR] : *contact_radius_;
  if (!(R > 0.0))
    reject(line, kWheelR,
           "column " + c.describe(kWheelR) + " has " + number(R) +
               " m; expected the contact radius, > 0");
  if (slip && V == 0.0)
    reject(line, kWheelSlipRatio,
           "column " + c.describe(kWheelSlipRatio) +
               " has a value while V = 0: the slip ratio is relative to V_x, undefined when the "
               "contact centre does not move; give the wheel's speed as omega_w instead");

  // SAE J670 to ISO W (physics.md §1.1): y and z turn over, x stays; so do the moments about
  // them, the yaw rate and the inclination. The slip angle, the slip ratio and the wheel's
  // spin are the same numbers in both.
  const double s = sae ? -1.0 : 1.0;
  const double gamma = s * v[kWheelGamma];
  const double psi_dot = given[kWheelPsiDot] ? s * v[kWheelPsiDot] : 0.0;
  const double N = s * Fz;

  const double Vx = V * std::cos(alpha);
  const double Vy = -V * std::sin(alpha);
  double Omega, vx;
  if (slip) {
    const double ratio = v[kWheelSlipRatio];
    Omega = spin ? v[kWheelOmegaW] : Vx * (1.0 + ratio) / re;
    vx = -Vx * ratio;  // V_x - Omega r_e with Omega r_e = V_x (1 + slip_ratio)
  } else {
    Omega = v[kWheelOmegaW];
    vx = Vx - Omega * re;
  }
  const double omega = psi_dot - Omega * std::sin(gamma);

  out.line.push_back(line);
  out.v_x.push_back(plus_zero(vx));
  out.v_y.push_back(plus_zero(Vy));
  out.omega.push_back(plus_zero(omega));
  out.N.push_back(N);
  out.R.push_back(R);
  out.tilt_sign.push_back(Omega > 0.0 ? 1.0 : Omega < 0.0 ? -1.0 : 0.0);
  // The resistances in the seed's convention (physics.md (1.7)) are minus the road's forces and
  // moments on the tire, but for the tilting couple, which is the overturning moment itself.
  const std::pair<int, double> channels[kChannelCount] = {
      {kWheelFx, -1.0}, {kWheelFy, -s}, {kWheelMz, -s}, {kWheelMy, -s}, {kWheelMx, 1.0}};
  for (int k = 0; k < kChannelCount; ++k) {
    const auto [slot, sign] = channels[k];
    const bool present = c.has(slot) && given[slot];
    out.value[k].push_back(present ? plus_zero(sign * v[slot]) : kNaN);
    out.present[k].push_back(present ? 1 : 0);
  }
}

}  // namespace frictionid::io_detail
