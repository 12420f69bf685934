#include "app/shimmy_report_model.hpp"

#include <nlohmann/json.hpp>

#include <frictionid/io/input_error.hpp>
#include <frictionid/io/provenance.hpp>
#include "io/small_file.hpp"

namespace frictionid::app {

ModelRequest shimmy_model_request(const ShimmyRequest& r) {
  if (r.from_report.empty()) return r.model;
  if (!r.model.params.empty())
    throw InputError("--from-report takes the parameters of the fit: no --param with it");
  const std::string text =
      io::read_small_file(r.from_report, "a report.json", "report", "a report.json");
  const std::string where = "--from-report " + r.from_report;
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception&) {
    throw InputError(where + ": not JSON; expected a report.json of frictionid fit");
  }
  if (!j.is_object() || !j.contains("model") || !j.contains("pressure") ||
      !j.contains("parameters") || !j["parameters"].is_object())
    throw InputError(where + ": no model, pressure and parameters; expected a report.json");
  const auto provenance = j.find("provenance");
  const std::string version = provenance != j.end() && provenance->is_object() &&
                                      provenance->contains("version") &&
                                      (*provenance)["version"].is_string()
                                  ? (*provenance)["version"].get<std::string>()
                                  : std::string("an unknown version");
  if (version != frictionid_version())
    throw InputError(where + ": written by frictionid " + version + "; this is frictionid " +
                     frictionid_version() + " (fit again, or give the parameters with --param)");
  try {
    ModelRequest m;
    m.model = j["model"].get<std::string>();
    m.pressure = j["pressure"].get<std::string>();
    m.contact = j.value("contact", std::string("circle"));
    const bool map = m.contact.rfind("map:", 0) == 0;
    m.pressure_given = !map;
    if (map) m.pressure = "hertz";
    for (const auto& [name, e] : j["parameters"].items()) {
      if (name == "q") continue;  // the spot's aspect is in `contact`
      if (!e.is_object() || !e.contains("value") || !e["value"].is_number())
        throw InputError(where + ": parameter '" + name + "' has no numeric value");
      m.params[name] = e["value"].get<double>();
    }
    return m;
  } catch (const nlohmann::json::exception&) {
    throw InputError(where + ": model, pressure or contact is not a string");
  }
}

}  // namespace frictionid::app
