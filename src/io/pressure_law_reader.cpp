#include <frictionid/io/pressure_law_reader.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <vector>

#include <frictionid/io/input_error.hpp>
#include "io/small_file.hpp"
#include "io/text.hpp"

namespace frictionid {
namespace {

using text::shown;

// Strict decimal parse of a whole field (io/text.hpp's grammar); a CR left by CRLF line ends is
// trimmed too.
bool parse_field(std::string_view field, double& out) {
  field = text::trim(field);
  while (!field.empty() && field.back() == '\r')
    field = text::trim(field.substr(0, field.size() - 1));
  return text::parse_double_strict(field, out) == nullptr;
}

// The coefficients divide by the law's moments: a law whose moments overflow or underflow
// (sigma0 near the double range, rho samples too close for their sigma0 step, a huge exponent)
// is rejected here instead of turning into NaN downstream.
bool moments_finite_and_positive(const model::PressureLaw<double>& law) {
  const auto m = model::law_moments(law);
  for (int k = 0; k < 6; ++k)
    if (!(std::isfinite(m[k]) && m[k] > 0.0)) return false;
  return true;
}

}  // namespace

model::PressureLaw<double> load_pressure_table(const std::string& path) {
  const std::string content = io::read_small_file(
      path, "a pressure table file", "pressure table file", "a pressure table (rho,sigma)");
  std::istringstream table(content);
  std::vector<double> rho, sigma;
  std::vector<std::size_t> lines;
  std::string line;
  std::size_t lineno = 0;
  bool header_seen = false;
  while (std::getline(table, line)) {
    ++lineno;
    if (lineno == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find('\r') != std::string::npos)
      throw InputError(path, lineno, 0,
                       "the line contains a carriage return (CR): the file seems to use CR-only "
                       "(classic Mac) line ends; expected LF or CRLF line ends");
    if (line.find_first_not_of(" \t") == std::string::npos || line[0] == '#') continue;
    if (!header_seen) {
      header_seen = true;
      double dummy;
      const auto comma = line.find(',');
      if (comma != std::string::npos && parse_field(line.substr(0, comma), dummy))
        throw InputError(path, lineno, 1,
                         "expected a header line (e.g. 'rho,sigma0'), found numbers");
      continue;
    }
    const auto comma = line.find(',');
    if (comma == std::string::npos || line.find(',', comma + 1) != std::string::npos)
      throw InputError(path, lineno, 1,
                       "expected two comma-separated fields 'rho,sigma0', found " + shown(line));
    double r, s;
    if (!parse_field(line.substr(0, comma), r))
      throw InputError(path, lineno, 1,
                       "rho: expected a finite number, found " + shown(line.substr(0, comma)));
    if (!parse_field(line.substr(comma + 1), s))
      throw InputError(path, lineno, 2,
                       "sigma0: expected a finite number, found " + shown(line.substr(comma + 1)));
    if (rho.size() == kMaxPressureTableSamples)
      throw InputError(path, lineno, 0,
                       "more than " + std::to_string(kMaxPressureTableSamples) +
                           " samples: the exact model's set-up integrates over every sample "
                           "(about half a millisecond each); resample the table, a few thousand "
                           "samples resolve any measured profile");
    rho.push_back(r);
    sigma.push_back(s);
    lines.push_back(lineno);
  }
  if (!header_seen) throw InputError(path, 0, 0, "the pressure table is empty");
  try {
    auto table = std::make_shared<const model::PressureTable>(rho, sigma);
    auto law = model::PressureLaw<double>::tabulated(std::move(table));
    if (!moments_finite_and_positive(law))
      throw InputError(path, 0, 0,
                       "the interpolated law's moments are not finite (sigma0 too close to the "
                       "double range, or rho samples too close together for their step in "
                       "sigma0); expected moderate sigma0 values, e.g. scaled to a maximum of 1");
    return law;
  } catch (const std::invalid_argument& e) {
    // Map "sample i: ..." back to the file line of that sample.
    const std::string what = e.what();
    std::size_t line_of_sample = 0, column = 0;
    if (what.rfind("sample ", 0) == 0) {
      const std::size_t i = std::strtoul(what.c_str() + 7, nullptr, 10);
      if (i < lines.size()) line_of_sample = lines[i];
      column = what.find("sigma0") != std::string::npos ? 2 : 1;
    }
    const auto colon = what.find(": ");
    const std::string reason =
        line_of_sample > 0 && colon != std::string::npos ? what.substr(colon + 2) : what;
    throw InputError(path, line_of_sample, column, reason);
  }
}

model::PressureLaw<double> parse_pressure_law(const std::string& spec) {
  using Law = model::PressureLaw<double>;
  if (spec == "uniform") return Law::uniform();
  if (spec == "hertz") return Law::hertz();
  if (spec == "parabolic") return Law::parabolic();
  if (spec.rfind("power:", 0) == 0) {
    double n;
    if (!parse_field(spec.substr(6), n))
      throw InputError("pressure law '" + spec + "': power:N needs a finite number N");
    if (n < 0.0) throw InputError("pressure law '" + spec + "': power:N needs N >= 0");
    const Law law = Law::power(n);
    if (!moments_finite_and_positive(law))
      throw InputError("pressure law '" + spec + "'" +
                       ": the law's moments underflow for so large an N; expected a moderate N");
    return law;
  }
  if (spec == "ring") return Law::ring();
  if (spec.rfind("annulus:", 0) == 0) {
    double inner;
    if (!parse_field(spec.substr(8), inner))
      throw InputError("pressure law '" + spec + "': annulus:B needs a finite number B");
    if (!(inner >= 0.0 && inner < 1.0))
      throw InputError("pressure law '" + spec + "'" +
                       ": annulus:B needs 0 <= B < 1 (B is the inner radius over the contact "
                       "radius; use ring for all load on the rim)");
    return Law::annulus(inner);
  }
  if (spec.rfind("table:", 0) == 0) {
    if (spec.size() == 6) throw InputError("pressure law 'table:': table:FILE needs a file name");
    return load_pressure_table(spec.substr(6));
  }
  throw InputError("unknown pressure law '" + spec +
                   "': expected uniform, hertz, parabolic, power:N (N >= 0), annulus:B "
                   "(0 <= B < 1), ring or table:FILE");
}

std::string pressure_law_label(const model::PressureLaw<double>& law, const std::string& spec) {
  if (law.kind == model::PressureKind::Table) return spec;
  if (law.kind == model::PressureKind::Power) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "power:%.17g", law.n);
    return buf;
  }
  if (law.kind == model::PressureKind::Annulus) {
    // The shortest text that reads back as the same B: "annulus:0.3", not 0.29999999999999999.
    char buf[64];
    for (int digits = 15; digits <= 17; ++digits) {
      std::snprintf(buf, sizeof buf, "annulus:%.*g", digits, law.n);
      if (std::strtod(buf + 8, nullptr) == law.n) break;
    }
    return buf;
  }
  return model::pressure_name(law.kind);
}

}  // namespace frictionid
