// frictionid generate: a synthetic dataset from any model, with its truth.
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>

#include <frictionid/io/dataset_writer.hpp>
#include <frictionid/io/input_error.hpp>
#include <frictionid/synthetic_data.hpp>
#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "cli/model_setup.hpp"
#include "cli/option_parsers.hpp"
#include "io/atomic_file.hpp"

namespace frictionid::cli {

namespace {
std::vector<double> parse_number_list(const std::string& option, const std::string& spec) {
  std::vector<double> out;
  std::size_t start = 0;
  while (start <= spec.size()) {
    const std::size_t comma = spec.find(',', start);
    const std::string item =
        spec.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    out.push_back(parse_number(option, item));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}
}  // namespace

int run_generate(const GenerateOptions& o) {
  const ModelSetup s = make_model_setup(o.model, o.pressure, o.params);
  if (o.output.empty()) throw InputError("generate needs --output FILE");
  if (o.rows == 0) throw InputError("--rows must be at least 1");
  if (!(o.noise >= 0.0) || !(o.noise_abs >= 0.0) || !std::isfinite(o.noise) ||
      !std::isfinite(o.noise_abs))
    throw InputError("--noise and --noise-abs must be finite and >= 0");
  if (o.sigma_columns && o.noise == 0.0 && o.noise_abs == 0.0)
    throw InputError(
        "--sigma-columns needs --noise or --noise-abs > 0 (a sigma of 0 is not usable)");
  SyntheticDesign d;
  d.rows = o.rows;
  d.eps_min = o.eps_min;
  d.eps_max = o.eps_max;
  if (!(d.eps_min > 0.0) || !(d.eps_max >= d.eps_min) || !std::isfinite(d.eps_max))
    throw InputError("--eps-min/--eps-max: need 0 < eps-min <= eps-max, finite");
  d.loads = parse_number_list("--loads", o.loads);
  for (double n : d.loads)
    if (!(n > 0.0)) throw InputError("--loads: every load must be > 0");
  if (!(o.R > 0.0) || !std::isfinite(o.R)) throw InputError("--R must be a finite number > 0");
  if (!(o.spin > 0.0) || !std::isfinite(o.spin))
    throw InputError("--spin must be a finite number > 0");
  d.contact_radius = o.R;
  d.spin = o.spin;
  d.slip_angles.clear();
  for (double deg : parse_number_list("--slip-angles", o.slip_angles_deg))
    d.slip_angles.push_back(deg * M_PI / 180.0);
  d.negative_slip = !o.forward_only;
  NoiseSpec noise{o.noise, o.noise_abs, o.sigma_columns};
  Dataset data = generate_dataset(s.kind, s.law, s.params, d, noise, o.seed);
  data.source = o.output;

  if (!o.truth.empty()) {
    nlohmann::ordered_json t = model_json(s);
    t["noise"] = {
        {"relative", o.noise}, {"absolute", o.noise_abs}, {"sigma_columns", o.sigma_columns}};
    t["seed"] = o.seed;
    t["rows"] = o.rows;
    t["design"] = {{"eps_min", d.eps_min},
                   {"eps_max", d.eps_max},
                   {"loads", d.loads},
                   {"R", d.contact_radius},
                   {"spin", d.spin},
                   {"slip_angles_deg", parse_number_list("--slip-angles", o.slip_angles_deg)},
                   {"negative_slip", d.negative_slip}};
    write_file_atomically(o.truth, t.dump(2) + "\n");
  }
  write_file_atomically(o.output, dataset_csv_text(data));
  std::cerr << "frictionid: wrote " << data.rows() << " rows to " << o.output
            << (o.truth.empty() ? "" : " and the truth to " + o.truth) << "\n";
  return kExitOk;
}

}  // namespace frictionid::cli
