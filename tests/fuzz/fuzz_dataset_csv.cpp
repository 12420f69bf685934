// libFuzzer target: the dataset CSV reader. Each input is written to a scratch file and read with
// load_dataset_csv, with and without channels required and with a column map. Rejections must be
// InputError (anything else escapes and is reported as a crash); an accepted dataset must satisfy
// the reader's documented guarantees (dataset_csv.hpp).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include <frictionid/io/dataset_csv.hpp>
#include <frictionid/io/input_error.hpp>
#include "app/option_parsers.hpp"
#include "fuzz_support.hpp"

namespace {

using frictionid::ColumnMap;
using frictionid::Dataset;
using frictionid::kChannelCount;

void check(const Dataset& d, bool require_channels) {
  const std::size_t n = d.rows();
  FRICTIONID_FUZZ_CHECK(n > 0);
  FRICTIONID_FUZZ_CHECK(d.line.size() == n && d.v_y.size() == n && d.omega.size() == n &&
                        d.N.size() == n && d.R.size() == n);
  for (std::size_t i = 0; i < n; ++i) {
    FRICTIONID_FUZZ_CHECK(d.line[i] >= 2 && (i == 0 || d.line[i] > d.line[i - 1]));
    FRICTIONID_FUZZ_CHECK(std::isfinite(d.v_x[i]) && std::isfinite(d.v_y[i]) &&
                          std::isfinite(d.omega[i]));
    FRICTIONID_FUZZ_CHECK(std::isfinite(d.N[i]) && d.N[i] > 0);
    FRICTIONID_FUZZ_CHECK(std::isfinite(d.R[i]) && d.R[i] > 0);
    bool any = false;
    for (int c = 0; c < kChannelCount; ++c) {
      FRICTIONID_FUZZ_CHECK(d.value[c].size() == n && d.present[c].size() == n);
      FRICTIONID_FUZZ_CHECK(d.sigma[c].empty() || d.sigma[c].size() == n);
      if (d.present[c][i]) {
        any = true;
        FRICTIONID_FUZZ_CHECK(std::isfinite(d.value[c][i]));
        if (!d.sigma[c].empty())
          FRICTIONID_FUZZ_CHECK(std::isfinite(d.sigma[c][i]) && d.sigma[c][i] > 0);
      } else {
        FRICTIONID_FUZZ_CHECK(std::isnan(d.value[c][i]));
      }
    }
    FRICTIONID_FUZZ_CHECK(any || !require_channels);
  }
}

void load(const std::string& path, const ColumnMap& columns, bool require_channels) {
  try {
    check(frictionid::load_dataset_csv(path, columns, require_channels), require_channels);
  } catch (const frictionid::InputError& e) {
    FRICTIONID_FUZZ_CHECK(e.what()[0] != '\0');
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // Every load costs a 48 MiB line buffer (fast-cpp-csv-parser), which ASan poisons page by
  // page; so the variants run only on inputs where they can make a difference.
  static frictionid::fuzz::ScratchFile file(".csv");
  const std::string& path = file.write(data, size);
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::string message;
  try {
    check(frictionid::load_dataset_csv(path), true);
  } catch (const frictionid::InputError& e) {
    message = e.what();
    FRICTIONID_FUZZ_CHECK(!message.empty());
  }
  if (message.find("channel") != std::string::npos) load(path, {}, false);
  if (text.find("speed") != std::string_view::npos || text.find("spin") != std::string_view::npos) {
    static const ColumnMap renamed = frictionid::parse_column_map("v_x=speed,omega=spin,T_x=Fx");
    load(path, renamed, true);
  }
  return 0;
}
