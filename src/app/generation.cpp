#include "app/generation.hpp"

#include <cmath>
#include <string>

#include <frictionid/io/dataset_writer.hpp>
#include <frictionid/io/input_error.hpp>
#include "app/option_parsers.hpp"
#include "io/atomic_file.hpp"

namespace frictionid::app {

GeneratedData generate(const GenerateRequest& r, FitObserver* observer) {
  GeneratedData g;
  g.setup = make_model_setup(r.model);
  if (r.rows < 1 || r.rows > kMaxGeneratedRows)
    throw InputError("--rows", 0, 0,
                     "got '" + std::to_string(r.rows) + "'; expected a whole number from 1 to " +
                         std::to_string(kMaxGeneratedRows));
  check_thread_option(r.threads);
  if (!(r.noise >= 0.0) || !(r.noise_abs >= 0.0) || !std::isfinite(r.noise) ||
      !std::isfinite(r.noise_abs))
    throw InputError("--noise and --noise-abs must be finite and >= 0");
  if (r.sigma_columns && r.noise == 0.0 && r.noise_abs == 0.0)
    throw InputError(
        "--sigma-columns needs --noise or --noise-abs > 0 (a sigma of 0 is not usable)");
  SyntheticDesign& d = g.design;
  d.rows = r.rows;
  d.eps_min = r.eps_min;
  d.eps_max = r.eps_max;
  if (!(d.eps_min > 0.0) || !(d.eps_max >= d.eps_min) || !std::isfinite(d.eps_max))
    throw InputError("--eps-min/--eps-max: need 0 < eps-min <= eps-max, finite");
  if (r.loads.empty()) throw InputError("--loads: expected at least one load");
  for (double n : r.loads)
    if (!(n > 0.0) || !std::isfinite(n)) throw InputError("--loads: every load must be > 0");
  d.loads = r.loads;
  if (!(r.R > 0.0) || !std::isfinite(r.R)) throw InputError("--R must be a finite number > 0");
  if (!(r.spin > 0.0) || !std::isfinite(r.spin))
    throw InputError("--spin must be a finite number > 0");
  d.contact_radius = r.R;
  d.spin = r.spin;
  if (r.slip_angles_deg.empty()) throw InputError("--slip-angles: expected at least one angle");
  d.slip_angles.clear();
  for (double deg : r.slip_angles_deg) {
    if (!std::isfinite(deg)) throw InputError("--slip-angles: every angle must be finite");
    d.slip_angles.push_back(deg * M_PI / 180.0);
  }
  d.negative_slip = !r.forward_only;
  const NoiseSpec noise{r.noise, r.noise_abs, r.sigma_columns};
  // An M_tilt column only where the model shows it (shows_tilt): a circle's file stays as it was.
  g.data = generate_dataset(g.setup.kind, g.setup.law, g.setup.params, d, noise, r.seed,
                            g.setup.contact, r.threads, observer);
  g.data.source = r.output;
  return g;
}

nlohmann::ordered_json truth_json(const GenerateRequest& r, const GeneratedData& g) {
  nlohmann::ordered_json t = model_json(g.setup);
  t["noise"] = {
      {"relative", r.noise}, {"absolute", r.noise_abs}, {"sigma_columns", r.sigma_columns}};
  t["seed"] = r.seed;
  t["rows"] = r.rows;
  const SyntheticDesign& d = g.design;
  t["design"] = {{"eps_min", d.eps_min},
                 {"eps_max", d.eps_max},
                 {"loads", d.loads},
                 {"R", d.contact_radius},
                 {"spin", d.spin},
                 {"slip_angles_deg", r.slip_angles_deg},
                 {"negative_slip", d.negative_slip}};
  return t;
}

void write_generated(const GenerateRequest& r, const GeneratedData& g) {
  if (r.output.empty()) throw InputError("generate needs --output FILE");
  if (!r.truth.empty()) write_file_atomically(r.truth, truth_json(r, g).dump(2) + "\n");
  write_file_atomically(r.output, dataset_csv_text(g.data));
}

}  // namespace frictionid::app
