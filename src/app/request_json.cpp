#include "app/request_json.hpp"

namespace frictionid::app {

namespace {

// The options of the fit itself.
nlohmann::ordered_json fit_options_json(const FitRequest& r) {
  nlohmann::ordered_json bounds = nlohmann::ordered_json::object();
  for (const auto& [name, lohi] : r.bounds) bounds[name] = {lohi.first, lohi.second};
  nlohmann::ordered_json j = {{"model", r.model}, {"pressure", r.pressure}};
  // The spot and the freed parameters only when they are not the defaults: a circle's options
  // (in every report's provenance and every journal key) stay what they were before spots.
  if (r.contact != "circle") j["contact"] = r.contact;
  j["fix"] = r.fix;
  if (!r.free.empty()) j["free"] = r.free;
  j.update(nlohmann::ordered_json{{"bounds", bounds},
                                  {"start", r.start},
                                  {"loss", r.loss},
                                  {"channels", r.channels},
                                  {"columns", r.columns.canonical_to_header},
                                  {"noise_model", r.noise_model},
                                  {"intervals", r.intervals},
                                  {"bootstrap", r.bootstrap},
                                  {"starts", r.starts},
                                  {"seed", r.seed},
                                  {"global_evaluations", r.global_evaluations},
                                  {"global_subsample", r.global_subsample},
                                  {"no_global", r.no_global},
                                  {"global_algorithm", r.global_algorithm}});
  return j;
}

}  // namespace

nlohmann::ordered_json fit_request_json(const FitRequest& r) {
  nlohmann::ordered_json j = fit_options_json(r);
  // How the data are read, where it is not the default: the options (in every report and every
  // journal key) of a native file read as before stay what they were.
  if (r.input_form != "auto") j["input_form"] = r.input_form;
  if (r.axes != "iso") j["axes"] = r.axes;
  if (r.contact_radius) j["contact_radius"] = *r.contact_radius;
  if (!r.keep.empty()) j["keep"] = r.keep;
  return j;
}

FitRequest fit_request_from_json(const nlohmann::ordered_json& j) {
  FitRequest r;
  r.model = j.at("model").get<std::string>();
  r.pressure = j.at("pressure").get<std::string>();
  r.contact = j.value("contact", std::string("circle"));
  r.fix = j.at("fix").get<ParameterValues>();
  if (j.contains("free")) r.free = j.at("free").get<std::vector<std::string>>();
  for (const auto& [name, lohi] : j.at("bounds").items())
    r.bounds[name] = {lohi.at(0).get<double>(), lohi.at(1).get<double>()};
  r.start = j.at("start").get<ParameterValues>();
  r.loss = j.at("loss").get<std::string>();
  r.channels = j.at("channels").get<std::vector<std::string>>();
  r.columns.canonical_to_header = j.at("columns").get<std::map<std::string, std::string>>();
  r.noise_model = j.at("noise_model").get<std::string>();
  r.intervals = j.at("intervals").get<std::string>();
  r.bootstrap = j.at("bootstrap").get<int>();
  r.starts = j.at("starts").get<int>();
  r.seed = j.at("seed").get<unsigned long long>();
  r.global_evaluations = j.at("global_evaluations").get<long>();
  r.global_subsample = j.at("global_subsample").get<std::size_t>();
  r.no_global = j.at("no_global").get<bool>();
  r.global_algorithm = j.at("global_algorithm").get<std::string>();
  r.input_form = j.value("input_form", std::string("auto"));
  r.axes = j.value("axes", std::string("iso"));
  if (j.contains("contact_radius")) r.contact_radius = j.at("contact_radius").get<double>();
  if (j.contains("keep")) r.keep = j.at("keep").get<std::vector<std::string>>();
  return r;
}

}  // namespace frictionid::app
