#include <frictionid/io/summary_table.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <frictionid/parameters.hpp>
#include "io/csv_cell.hpp"
#include "io/json_number.hpp"
#include "io/summary_columns.hpp"

namespace frictionid {

namespace {

using ojson = nlohmann::ordered_json;

std::optional<double> finite(double x) {
  return std::isfinite(x) ? std::optional<double>(x) : std::nullopt;
}
std::optional<double> finite(const std::optional<double>& x) {
  return x ? finite(*x) : std::nullopt;
}

std::string number_cell(const std::optional<double>& x) {
  if (!x || !std::isfinite(*x)) return "";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", *x);
  return buf;
}

std::optional<double> optional_number(const ojson& j, const char* key) {
  if (!j.contains(key) || j.at(key).is_null()) return std::nullopt;
  return j.at(key).get<double>();
}

// Names in order of first appearance over the rows.
template <class Items, class Name>
std::vector<std::string> union_of(const std::vector<SummaryRow>& rows, Items items, Name name) {
  std::vector<std::string> out;
  for (const auto& row : rows)
    for (const auto& item : items(row))
      if (std::find(out.begin(), out.end(), name(item)) == out.end()) out.push_back(name(item));
  return out;
}

}  // namespace

std::vector<Covariate> dataset_covariates(const Dataset& d) {
  const std::size_t n = d.rows();
  if (n == 0) return {};
  double N = 0.0, speed = 0.0, spin = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    N += d.N[i];
    speed += std::hypot(d.v_x[i], d.v_y.empty() ? 0.0 : d.v_y[i]);
    spin += std::abs(d.omega[i]) * d.R[i];
  }
  const double rows = static_cast<double>(n);
  const auto names = dataset_covariate_names();
  return {{names[0], N / rows}, {names[1], speed / rows}, {names[2], spin / rows}};
}

std::vector<std::string> dataset_covariate_names() {
  return {"mean_N", "mean_speed", "mean_omega_R"};
}

SummaryRow summary_row(const std::string& label, const FitResult& r,
                       std::vector<Covariate> covariates) {
  SummaryRow row;
  row.label = label;
  row.ok = true;
  row.rows = r.rows;
  for (const auto& p : r.parameters) {
    SummaryParameter s;
    s.name = p.name;
    s.value = p.value;
    s.std_error = finite(p.std_error);
    if (p.ci95) {
      s.ci95_lo = finite((*p.ci95)[0]);
      s.ci95_hi = finite((*p.ci95)[1]);
    }
    row.parameters.push_back(s);
  }
  row.cost = finite(r.cost);
  row.reduced_chi2 = finite(r.reduced_chi2);
  row.warnings = r.warnings;
  for (const auto& c : r.channel_summaries) {
    SummaryNoise n;
    n.channel = channel_name(c.channel);
    if (c.noise) {
      n.model = c.noise->model;
      n.s_abs = finite(c.noise->s_abs);
      n.s_rel = finite(c.noise->s_rel);
    }
    row.noise.push_back(n);
  }
  row.covariates = std::move(covariates);
  return row;
}

SummaryRow failed_summary_row(const std::string& label, std::size_t rows, const std::string& error,
                              std::vector<Covariate> covariates) {
  SummaryRow row;
  row.label = label;
  row.rows = rows;
  row.error = error.empty() ? "failed" : error;
  row.covariates = std::move(covariates);
  return row;
}

ojson summary_row_json(const SummaryRow& row) {
  ojson j;
  j["label"] = row.label;
  j["status"] = row.ok ? "ok" : "failed";
  j["rows"] = row.rows;
  ojson params = ojson::object();
  for (const auto& p : row.parameters) {
    ojson ci = nullptr;
    if (p.ci95_lo && p.ci95_hi) ci = ojson::array({json_number(p.ci95_lo), json_number(p.ci95_hi)});
    params[p.name] = {
        {"value", json_number(p.value)}, {"stderr", json_number(p.std_error)}, {"ci95", ci}};
  }
  j["parameters"] = params;
  j["cost"] = json_number(row.cost);
  j["reduced_chi2"] = json_number(row.reduced_chi2);
  j["warnings"] = row.warnings;
  j["error"] = row.ok ? ojson(nullptr) : ojson(row.error);
  ojson noise = ojson::object();
  for (const auto& n : row.noise)
    noise[n.channel] = {{"model", n.model.empty() ? ojson(nullptr) : ojson(n.model)},
                        {"s_abs", json_number(n.s_abs)},
                        {"s_rel", json_number(n.s_rel)}};
  j["noise"] = noise;
  ojson covariates = ojson::object();
  for (const auto& c : row.covariates)
    covariates[c.name] = std::holds_alternative<double>(c.value)
                             ? json_number(std::get<double>(c.value))
                             : ojson(std::get<std::string>(c.value));
  j["covariates"] = covariates;
  return j;
}

SummaryRow summary_row_from_json(const nlohmann::ordered_json& j) {
  try {
    SummaryRow row;
    row.label = j.at("label").get<std::string>();
    row.ok = j.at("status").get<std::string>() == "ok";
    row.rows = j.at("rows").get<std::size_t>();
    for (const auto& [name, p] : j.at("parameters").items()) {
      SummaryParameter s;
      s.name = name;
      s.value = p.at("value").get<double>();
      s.std_error = optional_number(p, "stderr");
      if (!p.at("ci95").is_null()) {
        s.ci95_lo = p.at("ci95").at(0).get<double>();
        s.ci95_hi = p.at("ci95").at(1).get<double>();
      }
      row.parameters.push_back(s);
    }
    row.cost = optional_number(j, "cost");
    row.reduced_chi2 = optional_number(j, "reduced_chi2");
    row.warnings = j.at("warnings").get<std::vector<std::string>>();
    if (!row.ok) row.error = j.at("error").get<std::string>();
    for (const auto& [channel, n] : j.at("noise").items()) {
      SummaryNoise s;
      s.channel = channel;
      if (!n.at("model").is_null()) s.model = n.at("model").get<std::string>();
      s.s_abs = optional_number(n, "s_abs");
      s.s_rel = optional_number(n, "s_rel");
      row.noise.push_back(s);
    }
    for (const auto& [name, v] : j.at("covariates").items()) {
      if (v.is_string())
        row.covariates.push_back({name, v.get<std::string>()});
      else
        row.covariates.push_back({name, v.is_null() ? NAN : v.get<double>()});
    }
    return row;
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(std::string("not a summary row: ") + e.what());
  }
}

std::vector<std::string> summary_parameter_names(const std::vector<SummaryRow>& rows) {
  auto names = union_of(
      rows, [](const SummaryRow& r) { return r.parameters; },
      [](const SummaryParameter& p) { return p.name; });
  std::stable_sort(names.begin(), names.end(), [](const std::string& a, const std::string& b) {
    return param_index(a).value_or(kParamCount) < param_index(b).value_or(kParamCount);
  });
  return names;
}

std::vector<std::string> summary_covariate_names(const std::vector<SummaryRow>& rows) {
  return union_of(
      rows, [](const SummaryRow& r) { return r.covariates; },
      [](const Covariate& c) { return c.name; });
}

std::string summary_csv(const std::vector<SummaryRow>& rows) {
  const auto params = summary_parameter_names(rows);
  auto channels = union_of(
      rows, [](const SummaryRow& r) { return r.noise; },
      [](const SummaryNoise& n) { return n.channel; });
  std::stable_sort(channels.begin(), channels.end(),
                   [](const std::string& a, const std::string& b) {
                     auto index = [](const std::string& name) {
                       for (Channel c : kAllChannels)
                         if (name == channel_name(c)) return static_cast<int>(c);
                       return kChannelCount;
                     };
                     return index(a) < index(b);
                   });
  const auto covariates = summary_covariate_names(rows);

  std::vector<std::string> header = {"label", "status", "rows"};
  for (const auto& p : params)
    for (const char* suffix : {"", "_stderr", "_ci95_lo", "_ci95_hi"}) header.push_back(p + suffix);
  for (const char* name : {"cost", "reduced_chi2", "warnings", "error"}) header.push_back(name);
  for (const auto& c : channels)
    for (const char* suffix : {"_model", "_s_abs", "_s_rel"})
      header.push_back("noise_" + c + suffix);
  for (const auto& c : covariates) header.push_back(c);

  std::string out;
  auto write_line = [&out](const std::vector<std::string>& cells) {
    for (std::size_t i = 0; i < cells.size(); ++i) out += (i ? "," : "") + csv_cell(cells[i]);
    out += "\n";
  };
  write_line(header);
  for (const auto& row : rows) {
    std::vector<std::string> cells = {row.label, row.ok ? "ok" : "failed",
                                      std::to_string(row.rows)};
    for (const auto& name : params) {
      const auto it = std::find_if(row.parameters.begin(), row.parameters.end(),
                                   [&](const SummaryParameter& p) { return p.name == name; });
      if (it == row.parameters.end()) {
        cells.insert(cells.end(), 4, "");
        continue;
      }
      for (const auto& x :
           {std::optional<double>(it->value), it->std_error, it->ci95_lo, it->ci95_hi})
        cells.push_back(number_cell(x));
    }
    cells.push_back(number_cell(row.cost));
    cells.push_back(number_cell(row.reduced_chi2));
    cells.push_back(row.ok ? std::to_string(row.warnings.size()) : "");
    cells.push_back(row.error);
    for (const auto& channel : channels) {
      const auto it = std::find_if(row.noise.begin(), row.noise.end(),
                                   [&](const SummaryNoise& n) { return n.channel == channel; });
      if (it == row.noise.end()) {
        cells.insert(cells.end(), 3, "");
        continue;
      }
      cells.push_back(it->model);
      cells.push_back(number_cell(it->s_abs));
      cells.push_back(number_cell(it->s_rel));
    }
    for (const auto& name : covariates) {
      const auto it = std::find_if(row.covariates.begin(), row.covariates.end(),
                                   [&](const Covariate& c) { return c.name == name; });
      if (it == row.covariates.end())
        cells.push_back("");
      else if (std::holds_alternative<double>(it->value))
        cells.push_back(number_cell(std::get<double>(it->value)));
      else
        cells.push_back(std::get<std::string>(it->value));
    }
    write_line(cells);
  }
  return out;
}

ojson summary_json(const std::vector<SummaryRow>& rows) {
  ojson runs = ojson::array();
  std::size_t failed = 0;
  for (const auto& row : rows) {
    runs.push_back(summary_row_json(row));
    if (!row.ok) ++failed;
  }
  ojson j;
  j["count"] = rows.size();
  j["failed"] = failed;
  j["runs"] = runs;
  return j;
}

}  // namespace frictionid
