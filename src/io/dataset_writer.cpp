#include <frictionid/io/dataset_writer.hpp>

#include <fmt/format.h>

namespace frictionid {

std::string dataset_csv_text(const Dataset& d) {
  std::string out = "v_x,v_y,omega,N,R";
  std::vector<Channel> channels, sigmas;
  for (Channel c : kAllChannels) {
    if (!d.has_channel(c)) continue;
    channels.push_back(c);
    out += std::string(",") + channel_name(c);
  }
  for (Channel c : channels)
    if (d.has_sigma(c)) {
      sigmas.push_back(c);
      out += std::string(",sigma_") + channel_name(c);
    }
  out += "\n";
  out.reserve(out.size() + d.rows() * 24 * (5 + channels.size() + sigmas.size()));
  auto num = [&](double v) { fmt::format_to(std::back_inserter(out), "{:.17g}", v); };
  for (std::size_t i = 0; i < d.rows(); ++i) {
    num(d.v_x[i]);
    out += ',';
    num(d.v_y[i]);
    out += ',';
    num(d.omega[i]);
    out += ',';
    num(d.N[i]);
    out += ',';
    num(d.R[i]);
    for (Channel c : channels) {
      out += ',';
      const int ci = static_cast<int>(c);
      if (d.present[ci][i]) num(d.value[ci][i]);  // empty field: not measured in this row
    }
    for (Channel c : sigmas) {
      out += ',';
      const int ci = static_cast<int>(c);
      if (d.present[ci][i]) num(d.sigma[ci][i]);
    }
    out += '\n';
  }
  return out;
}

}  // namespace frictionid
