// libFuzzer target: the option-value parsers (--param, --fix, --bounds, --channels, --columns,
// numbers, power:N, ellipse:Q) on the input as text, and the pressure-table reader (table:FILE)
// and the pressure-map reader (map:FILE) on the input as a file. Rejections must be InputError;
// accepted values must satisfy the documented contract.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

#include <frictionid/io/dataset_csv.hpp>
#include <frictionid/io/input_error.hpp>
#include <frictionid/io/pressure_law_reader.hpp>
#include <frictionid/io/pressure_map_reader.hpp>
#include "app/option_parsers.hpp"
#include "fuzz_support.hpp"
#include "io/text.hpp"

namespace {

template <typename F>
void expect_input_error_or_success(F&& f) {
  try {
    f();
  } catch (const frictionid::InputError& e) {
    FRICTIONID_FUZZ_CHECK(e.what()[0] != '\0');
  }
}

bool is_name(const std::string& s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'))
      return false;
  return true;
}

// An accepted pressure law is finite and non-negative across the spot and has finite, positive
// moments (the coefficients divide by them).
void check_law(const frictionid::model::PressureLaw<double>& law) {
  for (double rho : {0.0, 0.25, 0.5, 0.75, 0.999, 1.0}) {
    const double s = law(rho, 1.0 - rho);
    FRICTIONID_FUZZ_CHECK(std::isfinite(s) && s >= 0);
  }
  const auto m = frictionid::model::law_moments(law);
  for (int k = 0; k < 6; ++k) FRICTIONID_FUZZ_CHECK(std::isfinite(m[k]) && m[k] > 0);
}

// An accepted map is a grid of at least 2 x 2 strictly increasing, finite coordinates with
// finite samples >= 0 and a positive, finite load.
void check_map(const frictionid::model::PressureMap& m) {
  FRICTIONID_FUZZ_CHECK(m.nx() >= 2 && m.ny() >= 2);
  FRICTIONID_FUZZ_CHECK(m.sigma0.size() == m.nx() * m.ny());
  for (const auto* grid : {&m.x, &m.y})
    for (std::size_t i = 0; i < grid->size(); ++i) {
      FRICTIONID_FUZZ_CHECK(std::isfinite((*grid)[i]));
      if (i > 0) FRICTIONID_FUZZ_CHECK((*grid)[i - 1] < (*grid)[i]);
    }
  for (double s : m.sigma0) FRICTIONID_FUZZ_CHECK(std::isfinite(s) && s >= 0);
  const auto moments = frictionid::model::map_moments(m);
  FRICTIONID_FUZZ_CHECK(std::isfinite(moments.A0) && moments.A0 > 0);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);

  expect_input_error_or_success([&] {
    for (const auto& [name, value] : frictionid::parse_assignments("--param", text)) {
      FRICTIONID_FUZZ_CHECK(is_name(name));
      FRICTIONID_FUZZ_CHECK(std::isfinite(value));
    }
  });
  expect_input_error_or_success([&] {
    for (const auto& [name, range] : frictionid::parse_bounds("--bounds", text)) {
      FRICTIONID_FUZZ_CHECK(is_name(name));
      FRICTIONID_FUZZ_CHECK(std::isfinite(range.first) && std::isfinite(range.second));
      FRICTIONID_FUZZ_CHECK(range.first < range.second);
    }
  });
  expect_input_error_or_success([&] {
    for (const auto& name : frictionid::parse_name_list("--channels", text))
      FRICTIONID_FUZZ_CHECK(is_name(name));
  });
  expect_input_error_or_success([&] { frictionid::parse_column_map(text); });
  expect_input_error_or_success([&] {
    const double x = frictionid::parse_number("--vx", text);
    FRICTIONID_FUZZ_CHECK(std::isfinite(x));
  });
  {
    // Accepted numbers are finite and round-trip bit-identically through %.17g.
    double x = 0;
    if (frictionid::text::parse_double_strict(text, x) == nullptr) {
      FRICTIONID_FUZZ_CHECK(std::isfinite(x));
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.17g", x);
      double y = 0;
      FRICTIONID_FUZZ_CHECK(frictionid::text::parse_double_strict(buf, y) == nullptr);
      FRICTIONID_FUZZ_CHECK(std::memcmp(&x, &y, sizeof x) == 0);
    }
  }
  expect_input_error_or_success([&] {
    const auto law = frictionid::parse_pressure_law("power:" + text);
    FRICTIONID_FUZZ_CHECK(std::isfinite(law.n) && law.n >= 0);
    check_law(law);
  });

  expect_input_error_or_success([&] {
    const auto spot = frictionid::parse_contact_option("ellipse:" + text);
    FRICTIONID_FUZZ_CHECK(spot.q > 0 && spot.q <= 4);
  });

  static frictionid::fuzz::ScratchFile table(".csv");
  const std::string spec = "table:" + table.write(data, size);
  expect_input_error_or_success([&] { check_law(frictionid::parse_pressure_law(spec)); });
  expect_input_error_or_success([&] { check_map(*frictionid::load_pressure_map(table.path())); });
  return 0;
}
