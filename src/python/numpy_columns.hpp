// Copies between std::vector<double> and one-dimensional numpy arrays of float64.
#pragma once

#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <frictionid/dataset.hpp>

namespace frictionid::python {

using DoubleArray =
    pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>;

inline DoubleArray to_numpy(const std::vector<double>& v) {
  return DoubleArray(static_cast<pybind11::ssize_t>(v.size()), v.data());
}

inline std::vector<double> to_vector(const DoubleArray& a) {
  if (a.ndim() != 1) throw std::invalid_argument("expected a one-dimensional array");
  return std::vector<double>(a.data(), a.data() + a.size());
}

// The dataset's canonical columns as numpy arrays: kinematics, every measured channel (NaN where
// a row does not measure it) and every sigma column.
inline pybind11::dict dataset_columns(const Dataset& d) {
  pybind11::dict out;
  out["v_x"] = to_numpy(d.v_x);
  out["v_y"] = to_numpy(d.v_y);
  out["omega"] = to_numpy(d.omega);
  out["N"] = to_numpy(d.N);
  out["R"] = to_numpy(d.R);
  for (Channel c : kAllChannels)
    if (d.has_channel(c)) out[channel_name(c)] = to_numpy(d.value[static_cast<int>(c)]);
  for (Channel c : kAllChannels)
    if (d.has_sigma(c))
      out[pybind11::str(std::string("sigma_") + channel_name(c))] =
          to_numpy(d.sigma[static_cast<int>(c)]);
  return out;
}

}  // namespace frictionid::python
