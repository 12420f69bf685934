#include <frictionid/io/compare_report.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include <frictionid/io/report_writer.hpp>
#include "io/estimate_text.hpp"
#include "io/json_number.hpp"
#include "io/report_parts.hpp"
#include "io/report_transaction.hpp"

namespace frictionid {
namespace {

namespace fs = std::filesystem;
using ojson = nlohmann::ordered_json;

// Six digits with the exponent as "× 10ⁿ", "—" when not finite.
std::string g6(double x) {
  return std::isfinite(x) ? plain_number(x) : kNoNumber;
}

std::vector<std::string> all_parameter_names(const ModelComparison& c) {
  std::vector<std::string> names;
  for (const auto& f : c.fits)
    for (const auto& p : f.parameters)
      if (std::find(names.begin(), names.end(), p.name) == names.end()) names.push_back(p.name);
  return names;
}

// The spot of fit k ("circle" when contacts is empty).
const std::string& contact_of(const std::vector<std::string>& contacts, std::size_t k) {
  static const std::string circle = "circle";
  return k < contacts.size() ? contacts[k] : circle;
}

}  // namespace

bool compare_estimates_noise(const ModelComparison& c) {
  for (const auto& f : c.fits)
    for (const auto& cs : f.channel_summaries)
      if (cs.noise) return true;
  return false;
}

ModelComparison compare_named_variants(const ModelComparison& c,
                                       const std::vector<std::string>& contacts) {
  if (contacts.empty()) return c;
  ModelComparison named = c;
  for (std::size_t k = 0; k < c.fits.size(); ++k) {
    named.fits[k].model = compare_variant_name(c, contacts, k);
    if (c.fits[k].model == c.preferred_by_aic && c.delta_aic[k] == 0.0 &&
        named.preferred_by_aic == c.preferred_by_aic)
      named.preferred_by_aic = named.fits[k].model;
    if (c.fits[k].model == c.preferred_by_bic && c.delta_bic[k] == 0.0 &&
        named.preferred_by_bic == c.preferred_by_bic)
      named.preferred_by_bic = named.fits[k].model;
  }
  return named;
}

std::string compare_variant_name(const ModelComparison& c, const std::vector<std::string>& contacts,
                                 std::size_t k) {
  const std::string& contact = contact_of(contacts, k);
  return contact == "circle" ? c.fits[k].model : c.fits[k].model + "@" + contact;
}

std::string compare_variant_directory(const std::string& name) {
  std::string out;
  for (char ch : name) {
    const bool safe = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') ||
                      (ch >= '0' && ch <= '9') || ch == '.' || ch == '_' || ch == '+' ||
                      ch == '=' || ch == '@' || ch == '-';
    out += safe ? ch : '_';
  }
  return out;
}

std::vector<std::string> coefficient_notes(const ModelComparison& c) {
  std::vector<std::string> notes;
  if (c.implied_by_exact.empty()) return notes;
  std::optional<double> exact_kappa;
  for (const auto& f : c.fits)
    if (f.model_kind == ModelKind::Exact && !exact_kappa && f.parameter("kappa"))
      exact_kappa = f.parameter("kappa")->value;
  for (const auto& f : c.fits) {
    if (f.model_kind == ModelKind::Exact) continue;
    for (const char* name : {"a", "b", "b_tilde", "m", "p0"}) {
      const ParameterEstimate* p = find_param(f, name);
      if (!p || p->fixed || !c.implied_by_exact.count(name)) continue;
      const double implied = c.implied_by_exact.at(name);
      const double rel = (p->value - implied) / implied;
      // The implied value is at the exact fit's kappa; a warning of the closed-form fit itself
      // compares with the law's value at that fit's own kappa, which may differ.
      const std::string at =
          exact_kappa ? " (at the exact fit's kappa = " + g6(*exact_kappa) +
                            "; the closed-form fit's own warning, if any, "
                            "uses its own kappa = " +
                            g6(f.parameter("kappa") ? f.parameter("kappa")->value : 1.0) +
                            ", hence a different value)"
                      : std::string();
      if (std::fabs(rel) <= 0.05) {
        notes.push_back(
            fmt::format("{}: fitted {} = {} agrees within 5% with {} implied by the exact fit's "
                        "pressure shape{}: "
                        "the data are consistent with the slope-matched coefficient.",
                        f.model, name, g6(p->value), g6(implied), at));
      } else {
        notes.push_back(fmt::format(
            "{}: fitted {} = {} differs by {:+.0f}% from {} implied by the exact fit's pressure "
            "shape{}: the closed form's eps-shape is not the integral model's (errors of tens of "
            "percent near eps = 1, docs/physics.md section 3), so {} absorbs that shape error "
            "instead of "
            "measuring the pressure distribution; read it as a curve-fit constant.",
            f.model, name, g6(p->value), 100 * rel, g6(implied), at, name));
      }
    }
  }
  return notes;
}

nlohmann::ordered_json compare_json(const ModelComparison& c, const Provenance& provenance,
                                    const std::vector<std::string>& contacts) {
  const ModelComparison named = compare_named_variants(c, contacts);
  ojson j;
  j["rows"] = c.fits.empty() ? 0 : c.fits.front().rows;
  ojson channels = ojson::array();
  if (!c.fits.empty())
    for (Channel ch : c.fits.front().channels) channels.push_back(channel_name(ch));
  j["channels"] = channels;
  ojson models = ojson::array();
  for (std::size_t k = 0; k < c.fits.size(); ++k) {
    const FitResult& f = c.fits[k];
    ojson m;
    m["model"] = f.model;
    m["pressure"] = f.pressure;
    if (contact_of(contacts, k) != "circle") m["contact"] = contact_of(contacts, k);
    ojson params;
    for (const auto& p : f.parameters)
      params[p.name] = {{"value", json_number(p.value)},
                        {"stderr", json_number(p.std_error)},
                        {"fixed", p.fixed}};
    m["parameters"] = params;
    m["cost"] = json_number(f.cost);
    m["chi2"] = json_number(f.chi2);
    m["aic"] = json_number(f.aic);
    m["bic"] = json_number(f.bic);
    m["delta_aic"] = json_number(c.delta_aic[k]);
    m["delta_bic"] = json_number(c.delta_bic[k]);
    m["chi2_one_noise"] = json_number(
        k < c.chi2_common.size() ? std::optional<double>(c.chi2_common[k]) : std::nullopt);
    ojson rmse, ac;
    for (const auto& cs : f.channel_summaries)
      rmse[channel_name(cs.channel)] = json_number(cs.rmse);
    for (const auto& [name, v] : c.residual_autocorrelation[k]) ac[name] = json_number(v);
    m["rmse"] = rmse;
    m["residual_autocorrelation"] = ac;
    m["warnings"] = f.warnings;
    models.push_back(m);
  }
  j["models"] = models;
  j["preferred_by_aic"] = named.preferred_by_aic;
  j["preferred_by_bic"] = named.preferred_by_bic;
  j["one_noise_of"] =
      named.fits.empty()
          ? ojson(nullptr)
          : ojson(named.fits[std::min(named.common_noise_fit, named.fits.size() - 1)].model);
  ojson implied = ojson::object();
  for (const char* name : {"a", "b", "m", "b_tilde", "p0"})
    if (c.implied_by_exact.count(name)) implied[name] = json_number(c.implied_by_exact.at(name));
  j["implied_by_exact"] = implied;
  j["notes"] = coefficient_notes(named);
  j["provenance"] = provenance_json(provenance);
  return j;
}

std::string compare_markdown(const ModelComparison& compared, const std::vector<std::string>& plots,
                             const Provenance& provenance,
                             const std::vector<std::string>& contacts) {
  const ModelComparison c = compare_named_variants(compared, contacts);
  std::string md = "# frictionid compare\n\n";
  if (c.fits.empty()) return md + "No models were fitted.\n\n" + provenance_markdown(provenance);
  const FitResult& first = c.fits.front();
  const bool estimated = compare_estimates_noise(c);
  md += fmt::format(
      "{} rows; the same rows and channels for every model, {}. Preferred by AIC: **{}**; by "
      "BIC: **{}**.\n\n",
      first.rows,
      estimated ? "each whitened by its own noise estimate"
                : "the same whitening for every model (sigma columns or fixed scales)",
      c.preferred_by_aic, c.preferred_by_bic);
  md += "## Fit quality\n\n| model | AIC | ΔAIC | BIC | ΔBIC | χ², one noise |";
  for (const auto& cs : first.channel_summaries)
    md += fmt::format(" RMSE {0} [{1}] | residual lag-1 corr. {0} |", channel_name(cs.channel),
                      channel_unit(cs.channel));
  md += "\n|---|---|---|---|---|---|";
  for (std::size_t i = 0; i < first.channel_summaries.size(); ++i) md += "---|---|";
  md += "\n";
  for (std::size_t k = 0; k < c.fits.size(); ++k) {
    const FitResult& f = c.fits[k];
    md += fmt::format("| {} | {} | {} | {} | {} | {} |", f.model, g6(f.aic), g6(c.delta_aic[k]),
                      g6(f.bic), g6(c.delta_bic[k]),
                      k < c.chi2_common.size() ? g6(c.chi2_common[k]) : "—");
    for (const auto& cs : f.channel_summaries) {
      const auto it = c.residual_autocorrelation[k].find(channel_name(cs.channel));
      md += fmt::format(
          " {} | {} |", cs.rmse ? g6(*cs.rmse) : "—",
          it == c.residual_autocorrelation[k].end() ? "—" : fmt::format("{:.2f}", it->second));
    }
    md += "\n";
  }
  const std::string& whose = c.fits[std::min(c.common_noise_fit, c.fits.size() - 1)].model;
  md += "\n" +
        (estimated
             ? fmt::format(
                   "AIC and BIC include the log-likelihood of each model's own noise estimate "
                   "(docs/physics.md §8.7). "
                   "χ², one noise: every model's residuals divided by the sigma per row of the "
                   "noise estimated for {} (the model AIC prefers), so that these compare; each "
                   "model's own χ² (compare.json) is close to the number of cells for every model "
                   "and does not rank them.",
                   whose)
             : std::string("χ², one noise: every model's residuals divided by the same sigma per "
                           "row (the sigma columns or fixed scales, alike for every model)."));
  md +=
      " Residual lag-1 correlation: of those residuals in eps order along each curve of one slip "
      "direction, spin sign, tilt sign, load and radius, pooled; near 1 a systematic shape "
      "misfit, near 0 noise.\n\n## Parameters\n\n| parameter |";
  for (const auto& f : c.fits) md += " " + f.model + " |";
  if (!c.implied_by_exact.empty()) md += " implied by exact |";
  md += "\n|---|";
  for (std::size_t k = 0; k < c.fits.size(); ++k) md += "---|";
  if (!c.implied_by_exact.empty()) md += "---|";
  md += "\n";
  for (const auto& name : all_parameter_names(c)) {
    md += "| " + name + " |";
    for (const auto& f : c.fits) {
      const ParameterEstimate* p = find_param(f, name);
      if (!p)
        md += " |";
      else if (p->fixed)
        md += " " + g6(p->value) + " (fixed) |";
      else if (p->std_error)
        md += " " + estimate_text(p->value, p->std_error).joined() + " |";
      else
        md += " " + g6(p->value) + " (not determined) |";
    }
    if (!c.implied_by_exact.empty())
      md += c.implied_by_exact.count(name) ? " " + g6(c.implied_by_exact.at(name)) + " |" : " |";
    md += "\n";
  }
  const auto notes = coefficient_notes(c);
  md += "\n## What the coefficients mean\n\n";
  if (notes.empty()) md += "- no exact fit to compare with\n";
  for (const auto& n : notes) md += "- " + n + "\n";
  md += "\nThe same comparison on one page, plots inline: [compare.html](compare.html).\n";
  md += "\n## Per-model reports\n\n";
  for (const auto& f : c.fits)
    md += fmt::format("- [{}]({}/report.md)\n", f.model, compare_variant_directory(f.model));
  md += "\n" + provenance_markdown(provenance);
  if (!plots.empty()) {
    md +=
        "\n## Plots\n\nEach channel divided by N (forces) or N R (torques) and by its parity "
        "sign, against eps.\n\n";
    for (const auto& p : plots) md += fmt::format("![{}]({})\n\n", p, p);
  }
  return md;
}

std::vector<std::string> write_compare_report(const std::string& dir, const ModelComparison& c,
                                              const Dataset& d, const Provenance& provenance,
                                              const std::vector<std::string>& contacts,
                                              const std::function<bool()>& stop) {
  // Two fits whose reports would share a directory (the same model and spot) are refused
  // before anything is written.
  std::vector<std::string> subdirectories;
  for (std::size_t k = 0; k < c.fits.size(); ++k) {
    const std::string sub = compare_variant_directory(compare_variant_name(c, contacts, k));
    if (std::find(subdirectories.begin(), subdirectories.end(), sub) != subdirectories.end())
      throw std::invalid_argument("two compared fits would write their reports to " + dir + "/" +
                                  sub + "; compare each model on a spot once");
    subdirectories.push_back(sub);
  }
  // Every file of the comparison, the models' reports too, in one transaction.
  ReportTransaction transaction(dir, stop);
  const fs::path out = transaction.staging();
  std::vector<std::string> names;
  for (std::size_t k = 0; k < c.fits.size(); ++k) {
    const fs::path sub = out / subdirectories[k];
    std::error_code ec;
    fs::create_directory(sub, ec);
    if (ec)
      throw std::runtime_error("cannot create " + (fs::path(dir) / subdirectories[k]).string() +
                               ": " + ec.message());
    ReportOptions model_options;
    model_options.provenance = provenance;
    model_options.contact = contact_of(contacts, k);
    for (const auto& w : write_report_files(sub, c.fits[k], d, model_options))
      names.push_back((fs::path(subdirectories[k]) / w).string());
  }
  write_staged_file(
      out / "compare.json",
      compare_json(c, provenance, contacts).dump(2, ' ', false, ojson::error_handler_t::replace) +
          "\n");
  names.push_back("compare.json");

  const ModelComparison named = compare_named_variants(c, contacts);
  const std::vector<ReportPlot> plot_list = compare_plots(named, d);
  std::vector<std::string> plots;
  for (const auto& p : plot_list) plots.push_back(p.file);
  write_staged_pages(out, "compare", compare_markdown(named, plots, provenance),
                     compare_html_page(named, plot_list, provenance), plot_list, names);
  transaction.commit();
  std::vector<std::string> written;
  for (const auto& n : names) written.push_back((fs::path(dir) / n).string());
  return written;
}

}  // namespace frictionid
