#include "io/pressure_spec.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <vector>

#include "io/input_error.hpp"

namespace frictionid {
namespace {

// Strict decimal parse of a whole field: no trailing text, finite, not hex.
bool parse_field(const std::string& text, double& out) {
  std::size_t b = text.find_first_not_of(" \t");
  std::size_t e = text.find_last_not_of(" \t\r");
  if (b == std::string::npos) return false;
  const std::string t = text.substr(b, e - b + 1);
  if (t.find_first_of("xXpP") != std::string::npos) return false;
  errno = 0;
  char* end = nullptr;
  out = std::strtod(t.c_str(), &end);
  return end == t.c_str() + t.size() && errno != ERANGE && std::isfinite(out);
}

}  // namespace

model::PressureLaw<double> load_pressure_table(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, 0, "cannot open the pressure table file");
  std::vector<double> rho, sigma;
  std::vector<std::size_t> lines;
  std::string line;
  std::size_t lineno = 0;
  bool header_seen = false;
  while (std::getline(in, line)) {
    ++lineno;
    if (lineno == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    if (!line.empty() && line.back() == '\r') line.pop_back();
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
                       "expected two comma-separated fields 'rho,sigma0', found '" + line + "'");
    double r, s;
    if (!parse_field(line.substr(0, comma), r))
      throw InputError(path, lineno, 1,
                       "rho: expected a finite number, found '" + line.substr(0, comma) + "'");
    if (!parse_field(line.substr(comma + 1), s))
      throw InputError(path, lineno, 2,
                       "sigma0: expected a finite number, found '" + line.substr(comma + 1) + "'");
    rho.push_back(r);
    sigma.push_back(s);
    lines.push_back(lineno);
  }
  if (!header_seen) throw InputError(path, 0, 0, "the pressure table is empty");
  try {
    auto table = std::make_shared<const model::PressureTable>(rho, sigma);
    return model::PressureLaw<double>::tabulated(std::move(table));
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
      throw InputError("--pressure " + spec + ": power:N needs a finite number N");
    if (n < 0.0) throw InputError("--pressure " + spec + ": power:N needs N >= 0");
    return Law::power(n);
  }
  if (spec.rfind("table:", 0) == 0) {
    if (spec.size() == 6) throw InputError("--pressure table:FILE needs a file name");
    return load_pressure_table(spec.substr(6));
  }
  throw InputError("--pressure '" + spec +
                   "': expected uniform, hertz, parabolic, power:N (N >= 0) or table:FILE");
}

std::string pressure_law_label(const model::PressureLaw<double>& law, const std::string& spec) {
  if (law.kind == model::PressureKind::Table) return spec;
  if (law.kind == model::PressureKind::Power) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "power:%.17g", law.n);
    return buf;
  }
  return model::pressure_name(law.kind);
}

}  // namespace frictionid
