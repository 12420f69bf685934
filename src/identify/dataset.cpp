#include <frictionid/dataset.hpp>

#include <algorithm>
#include <stdexcept>

namespace frictionid {

Dataset Dataset::subsample(std::size_t max_rows) const {
  if (max_rows == 0) throw std::invalid_argument("a subsample needs at least one row");
  const std::size_t stride = std::max<std::size_t>(1, (rows() + max_rows - 1) / max_rows);
  Dataset sub;
  sub.source = source;
  auto take = [stride](const auto& column, auto& out) {
    for (std::size_t i = 0; i < column.size(); i += stride) out.push_back(column[i]);
  };
  take(line, sub.line);
  take(v_x, sub.v_x);
  take(v_y, sub.v_y);
  take(omega, sub.omega);
  take(N, sub.N);
  take(R, sub.R);
  take(tilt_sign, sub.tilt_sign);
  for (int c = 0; c < kChannelCount; ++c) {
    take(value[c], sub.value[c]);
    take(present[c], sub.present[c]);
    take(sigma[c], sub.sigma[c]);
  }
  return sub;
}

}  // namespace frictionid
