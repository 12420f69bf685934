// Reading a request's data, the rolling direction, the kept columns (app/data_input.hpp).
#include "app/data_input.hpp"

#include <algorithm>
#include <cmath>

#include <frictionid/io/input_error.hpp>
#include <frictionid/parameters.hpp>

namespace frictionid::app {

DatasetReadOptions dataset_read_options(const FitRequest& r) {
  DatasetReadOptions o;
  if (r.input_form == "auto")
    o.form = InputForm::Auto;
  else if (r.input_form == "native")
    o.form = InputForm::Native;
  else if (r.input_form == "wheel")
    o.form = InputForm::Wheel;
  else
    throw InputError("--input-form '" + r.input_form + "': expected auto, native or wheel");
  if (r.axes == "iso")
    o.axes = Axes::Iso;
  else if (r.axes == "sae")
    o.axes = Axes::Sae;
  else
    throw InputError("--axes '" + r.axes + "': expected iso or sae");
  if (r.contact_radius && !(std::isfinite(*r.contact_radius) && *r.contact_radius > 0.0))
    throw InputError("--contact-radius: expected the contact radius R > 0 [m]");
  o.contact_radius = r.contact_radius;
  o.columns = r.columns;
  return o;
}

LoadedDataset load_fit_data(const FitRequest& r, const std::string& path) {
  return read_dataset(path, dataset_read_options(r));
}

DataForm fit_data_form(const FitRequest& r, const std::string& path) {
  return inspect_dataset_form(path, dataset_read_options(r));
}

void check_rolling_direction(const FitSettings& s, const Dataset& d) {
  if (d.tilt_sign.empty()) return;
  const auto row = std::find(d.tilt_sign.begin(), d.tilt_sign.end(), 0.0);
  if (row == d.tilt_sign.end()) return;
  const auto used = s.used_parameters(d.has_channel(Channel::M_tilt));
  std::string loose;
  for (int i : {static_cast<int>(kH), static_cast<int>(kHy)}) {
    if (std::find(used.begin(), used.end(), i) == used.end()) continue;
    const ParameterSetting& p = s.params[i];
    if (!(p.fixed && p.initial == 0.0))
      loose += std::string(loose.empty() ? "" : " and ") + param_names()[i];
  }
  if (loose.empty()) return;
  const std::size_t i = static_cast<std::size_t>(row - d.tilt_sign.begin());
  throw InputError(d.source, i < d.line.size() ? d.line[i] : 0, 0,
                   "the wheel does not turn in this row (Omega = 0), so the pressure tilt, which "
                   "follows the rolling direction sgn(Omega), has no direction there; the fit "
                   "has " +
                       loose +
                       " free (or fixed away from 0): fix them at 0 (--fix h=0,h_y=0) or leave "
                       "out the rows where the wheel stands still");
}

std::vector<Covariate> kept_columns(const Dataset& d, const std::vector<std::string>& keep) {
  std::vector<Covariate> out;
  for (const auto& name : keep) {
    const auto it = std::find(d.extra_names.begin(), d.extra_names.end(), name);
    if (it == d.extra_names.end()) {
      std::string list;
      for (const auto& n : d.extra_names) list += (list.empty() ? "" : ", ") + n;
      throw InputError(d.source, 1, 0,
                       "--keep: no column '" + name + "' (the columns it can keep: " +
                           (list.empty() ? std::string("none") : list) + ")");
    }
    const auto& values = d.extra_values[static_cast<std::size_t>(it - d.extra_names.begin())];
    std::vector<std::string> distinct;
    for (const auto& v : values)
      if (std::find(distinct.begin(), distinct.end(), v) == distinct.end()) distinct.push_back(v);
    std::string joined;
    for (const auto& v : distinct) joined += (joined.empty() ? "" : "|") + v;
    out.push_back({name, joined});
  }
  return out;
}

}  // namespace frictionid::app
