// report.json: docs/design.md's keys in its order, parameters in FitResult order.
#include <frictionid/io/report_writer.hpp>

#include "io/json_number.hpp"

namespace frictionid {

using ojson = nlohmann::ordered_json;

namespace {
ojson interval(const std::optional<std::array<double, 2>>& ci) {
  return ci ? ojson::array({json_number((*ci)[0]), json_number((*ci)[1])}) : ojson();
}
}  // namespace

nlohmann::ordered_json report_json(const FitResult& r, const Provenance& p,
                                   const std::string& contact) {
  ojson j = report_json(r, contact);
  j["provenance"] = provenance_json(p);
  return j;
}

nlohmann::ordered_json report_json(const FitResult& r, const std::string& contact) {
  ojson j = ojson::object();
  j["model"] = r.model;
  j["pressure"] = r.pressure;
  if (contact != "circle") j["contact"] = contact;
  j["rows"] = r.rows;
  ojson channels = ojson::array();
  for (Channel c : r.channels) channels.push_back(channel_name(c));
  j["channels"] = std::move(channels);

  ojson params = ojson::object();
  for (const auto& p : r.parameters) {
    ojson e = ojson::object();
    e["value"] = json_number(p.value);
    e["stderr"] = json_number(p.std_error);
    e["ci95"] = interval(p.ci95);
    e["fixed"] = p.fixed;
    e["at_bound"] = p.at_bound;
    e["initial"] = json_number(p.initial);
    e["lower"] = json_number(p.lower);
    e["upper"] = json_number(p.upper);
    e["stderr_sandwich"] = json_number(p.std_error_sandwich);
    e["ci95_sandwich"] = interval(p.ci95_sandwich);
    if (p.ci95_profile) {
      e["ci95_profile"] = interval(p.ci95_profile);
      e["profile_closed"] = {p.profile_closed[0], p.profile_closed[1]};
    }
    if (p.ci95_bootstrap) {
      e["ci95_bootstrap"] = interval(p.ci95_bootstrap);
      e["stderr_bootstrap"] = json_number(p.std_error_bootstrap);
    }
    params[p.name] = std::move(e);
  }
  j["parameters"] = std::move(params);

  ojson names = ojson::array();
  for (const auto& n : r.correlation_names) names.push_back(n);
  ojson matrix = ojson::array();
  for (const auto& row : r.correlation) {
    ojson jr = ojson::array();
    for (double x : row) jr.push_back(json_number(x));
    matrix.push_back(std::move(jr));
  }
  j["correlation"] = {{"names", std::move(names)}, {"matrix", std::move(matrix)}};

  ojson st = ojson::object();
  st["cost"] = json_number(r.cost);
  st["chi2"] = json_number(r.chi2);
  st["reduced_chi2"] = json_number(r.reduced_chi2);
  st["aic"] = json_number(r.aic);
  st["bic"] = json_number(r.bic);
  st["dof"] = r.dof;
  st["residuals"] = r.residuals;
  ojson rmse = ojson::object(), r2 = ojson::object(), scales = ojson::object(),
        channel_rows = ojson::object();
  for (const auto& s : r.channel_summaries) {
    const char* name = channel_name(s.channel);
    rmse[name] = json_number(s.rmse);
    r2[name] = json_number(s.r2);
    scales[name] = {{"sigma", json_number(s.scale)}, {"source", s.scale_source}};
    channel_rows[name] = s.rows;
  }
  st["rmse"] = std::move(rmse);
  st["r2"] = std::move(r2);
  st["scales"] = std::move(scales);
  st["channel_rows"] = std::move(channel_rows);  // extra key: rows measuring each channel
  st["covariance_scaled_by_reduced_chi2"] = r.covariance_scaled_by_reduced_chi2;
  ojson noise = ojson::object();
  for (const auto& s : r.channel_summaries) {
    if (!s.noise) continue;
    noise[channel_name(s.channel)] = {{"model", s.noise->model},
                                      {"s_abs", json_number(s.noise->s_abs)},
                                      {"s_rel", json_number(s.noise->s_rel)},
                                      {"floor", json_number(s.noise->floor)}};
  }
  st["noise_model"] = {{"setting", r.noise_model},
                       {"iterations", r.noise_iterations},
                       {"channels", std::move(noise)}};
  st["loss"] = r.loss;
  j["statistics"] = std::move(st);

  ojson gs = ojson::object();
  gs["algorithm"] = r.global.algorithm;
  gs["starts"] = r.global.starts;
  gs["reached_best"] = r.global.reached_best;
  gs["evaluations"] = r.global.evaluations;
  gs["subsample_rows"] = r.global.subsample_rows;
  gs["local_fits_on_subsample"] = r.global.local_fits_on_subsample;
  gs["seed"] = r.global.seed;
  j["global_search"] = std::move(gs);

  ojson so = ojson::object();
  so["iterations"] = r.solver.iterations;
  so["termination"] = r.solver.termination;
  // Wall time would make two runs of the same fit differ byte-wise: the key stays (docs/design.md)
  // but holds null; the CLI prints the times on stdout.
  so["time_s"] = nullptr;
  so["converged"] = r.solver.converged;
  j["solver"] = std::move(so);

  ojson warnings = ojson::array();
  for (const auto& w : r.warnings) warnings.push_back(w);
  j["warnings"] = std::move(warnings);
  // Which interval the report puts first; ci95 stays the covariance's (docs/design.md §4).
  j["interval_method"] = r.interval_method;
  j["bootstrap_replicates"] = r.bootstrap_replicates;
  return j;
}

}  // namespace frictionid
