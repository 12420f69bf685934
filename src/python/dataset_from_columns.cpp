#include "python/dataset_from_columns.hpp"

#include <cmath>
#include <limits>
#include <utility>

#include <fmt/format.h>

#include <frictionid/io/input_error.hpp>

namespace frictionid::python {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

Dataset dataset_from_columns(std::map<std::string, std::vector<double>> columns,
                             const std::string& source,
                             const std::vector<std::string>& row_labels) {
  // A DataFrame's rows are named by their index label (what df.loc takes), others by position.
  const auto row_name = [&](std::size_t i) {
    if (i < row_labels.size())
      return fmt::format("row with index {} (row {} of the frame)", row_labels[i], i + 1);
    return fmt::format("row {} (index {})", i + 1, i);
  };
  const char* kRequired[] = {"v_x", "omega", "N", "R"};
  for (const char* name : kRequired)
    if (!columns.count(name))
      throw InputError(source, 0, 0,
                       fmt::format("no column '{}'; expected columns v_x, omega, N, R (v_y "
                                   "optional) and at least one of T_x, T_y, M_z, M_roll, "
                                   "M_tilt",
                                   name));
  bool any_channel_column = false;
  for (Channel c : kAllChannels) any_channel_column |= columns.count(channel_name(c)) > 0;
  if (!any_channel_column)
    throw InputError(source, 0, 0,
                     "no channel column; expected at least one of T_x, T_y, M_z, M_roll, "
                     "M_tilt");

  const std::size_t rows = columns.at("v_x").size();
  for (const auto& [name, values] : columns)
    if (values.size() != rows)
      throw InputError(source, 0, 0,
                       fmt::format("column '{}' has {} rows, column 'v_x' has {}; expected "
                                   "columns of one length",
                                   name, values.size(), rows));
  if (rows == 0) throw InputError(source, 0, 0, "no rows; expected at least one measurement row");

  Dataset d;
  d.source = source;
  const auto column = [&](const char* name) -> std::vector<double>* {
    const auto it = columns.find(name);
    return it == columns.end() ? nullptr : &it->second;
  };
  // Kinematics: every row, finite; N and R > 0.
  const auto kinematics = [&](const char* name, bool positive, std::vector<double>& out) {
    auto* values = column(name);
    if (!values) {
      out.assign(rows, 0.0);  // only v_y may be absent
      return;
    }
    for (std::size_t i = 0; i < rows; ++i) {
      const double x = (*values)[i];
      if (!std::isfinite(x) || (positive && !(x > 0.0)))
        throw InputError(source, 0, 0,
                         fmt::format("{}: column {} has {}; expected a finite number{}",
                                     row_name(i), name, x, positive ? " > 0" : ""));
    }
    out = std::move(*values);
  };
  kinematics("v_x", false, d.v_x);
  kinematics("v_y", false, d.v_y);
  kinematics("omega", false, d.omega);
  kinematics("N", true, d.N);
  kinematics("R", true, d.R);

  for (Channel c : kAllChannels) {
    const int ci = static_cast<int>(c);
    const std::string name = channel_name(c);
    auto* values = column(name.c_str());
    auto* sigma = column(("sigma_" + name).c_str());
    d.present[ci].assign(rows, 0);
    if (!values) {
      d.value[ci].assign(rows, kNaN);
      if (sigma) d.sigma[ci].assign(rows, kNaN);
      continue;
    }
    for (std::size_t i = 0; i < rows; ++i) {
      const double x = (*values)[i];
      if (std::isnan(x)) {
        if (sigma) (*sigma)[i] = kNaN;  // as the CSV reader: no sigma where no value
        continue;
      }
      if (!std::isfinite(x))
        throw InputError(source, 0, 0,
                         fmt::format("{}: column {} has {}; expected a finite number or NaN "
                                     "(not measured)",
                                     row_name(i), name, x));
      d.present[ci][i] = 1;
      if (!sigma) continue;
      const double s = (*sigma)[i];
      if (!(s > 0.0) || !std::isfinite(s))
        throw InputError(source, 0, 0,
                         fmt::format("{}: column sigma_{} has {} while {} is given; expected a "
                                     "finite standard deviation > 0",
                                     row_name(i), name, s, name));
    }
    d.value[ci] = std::move(*values);
    if (sigma) d.sigma[ci] = std::move(*sigma);
  }
  for (std::size_t i = 0; i < rows; ++i) {
    bool any = false;
    for (int c = 0; c < kChannelCount; ++c) any |= d.present[c][i] != 0;
    if (!any)
      throw InputError(source, 0, 0,
                       fmt::format("{}: no measured channel in this row; expected a value in "
                                   "at least one of the channel columns",
                                   row_name(i)));
  }
  return d;
}

}  // namespace frictionid::python
