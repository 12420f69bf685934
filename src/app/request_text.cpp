#include "app/request_text.hpp"

#include <frictionid/io/input_error.hpp>
#include "app/option_parsers.hpp"

namespace frictionid::app {

void apply(const FitText& text, FitRequest& r) {
  if (!text.start.empty()) r.start = parse_assignments("--param", text.start);
  if (!text.bounds.empty()) r.bounds = parse_bounds("--bounds", text.bounds);
  if (!text.fix.empty()) r.fix = parse_assignments("--fix", text.fix);
  if (!text.channels.empty()) r.channels = parse_name_list("--channels", text.channels);
  if (!text.free.empty()) r.free = parse_name_list("--free", text.free);
  r.columns = parse_column_map(text.columns);
}

ParameterValues parameter_values(const std::string& param_text) {
  return param_text.empty() ? ParameterValues{} : parse_assignments("--param", param_text);
}

std::vector<std::string> shared_names(const std::string& text) {
  std::vector<std::string> out;
  if (text.empty()) return out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    const std::string name = text.substr(start, comma == std::string::npos ? comma : comma - start);
    if (name.empty())
      throw InputError("--shared: expected P[,P], e.g. kappa,h; got '" + text + "'");
    out.push_back(name);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

std::vector<std::string> name_list(const std::string& option, const std::string& text) {
  return text.empty() ? std::vector<std::string>{} : parse_name_list(option, text);
}

}  // namespace frictionid::app
