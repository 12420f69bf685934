// report.md: the fit in words and tables, linking the plots that exist.
#include <frictionid/io/report_writer.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "io/estimate_text.hpp"
#include "io/report_parts.hpp"

namespace frictionid {
namespace {

// Markdown helpers

std::string fixed2(double x) {
  if (!std::isfinite(x)) return "—";
  std::string s = fmt::format("{:.2f}", x);
  if (s == "-0.00") s = "0.00";  // a tiny negative correlation is not worth a sign
  return s;
}

// Text placed inside a table cell: a '|' would end the cell, a newline the row.
std::string cell(const std::string& s) {
  std::string out;
  for (char ch : s) {
    if (ch == '|')
      out += "\\|";
    else if (ch == '\n' || ch == '\r')
      out += ' ';
    else
      out += ch;
  }
  return out;
}

// Text on one Markdown line (a bullet): a newline would start a new paragraph.
std::string one_line(const std::string& s) {
  std::string out = s;
  std::replace(out.begin(), out.end(), '\n', ' ');
  std::replace(out.begin(), out.end(), '\r', ' ');
  return out;
}

}  // namespace

std::string report_markdown(const FitResult& r) {
  return report_markdown(r, default_plot_files(r));
}

std::string report_markdown(const FitResult& r, const std::vector<std::string>& plot_files,
                            const Provenance& provenance, const std::string& contact) {
  std::string md;
  auto line = [&md](const std::string& s) { (md += s) += '\n'; };

  line(fmt::format("# frictionid fit: model {}, pressure {}{}", one_line(r.model),
                   one_line(r.pressure), one_line(contact_words(contact))));
  line("");
  line(fmt::format("{} rows; fitted channels: {}; loss: {}.", r.rows, join_channels(r.channels),
                   r.loss));
  line("");
  // The answer first, before the details (value ± stderr, relative error).
  if (!r.parameters.empty()) {
    std::string result = "**Result:** ";
    const auto items = result_items(r);
    for (std::size_t i = 0; i < items.size(); ++i) result += (i ? "; " : "") + one_line(items[i]);
    line(result + ".");
    line("");
  }
  line("The same report on one page, plots inline: [report.html](report.html).");
  line("");

  line("## Parameters");
  line("");
  const bool boot = r.bootstrap_replicates > 0;
  auto interval = [](const std::optional<std::array<double, 2>>& ci) {
    if (!ci) return std::string("—");
    const auto [lo, hi] = interval_text((*ci)[0], (*ci)[1]);
    return "[" + lo + ", " + hi + "]";
  };
  line(std::string("| name | value ± stderr | 95% CI | sandwich stderr |") +
       (boot ? " bootstrap stderr | bootstrap 95% CI |" : "") +
       " initial | bounds | note | 95% CI method |");
  line(std::string("|---|---|---|---|") + (boot ? "---|---|" : "") + "---|---|---|---|");
  for (const auto& p : r.parameters) {
    std::string row = fmt::format(
        "| {} | {} | {} | {} |", cell(p.name), estimate_text(p.value, p.std_error).joined(),
        interval(chosen_interval(r, p)), stderr_text(p.std_error_sandwich));
    if (boot)
      row +=
          fmt::format(" {} | {} |", stderr_text(p.std_error_bootstrap), interval(p.ci95_bootstrap));
    line(row + fmt::format(" {} | [{}, {}] | {} | {} |", num(p.initial), num(p.lower), num(p.upper),
                           parameter_note(p, "at bound (stderr not meaningful)", "not determined"),
                           cell(interval_method(r, p))));
  }
  line("");
  line(std::string("95% CI: ") + interval_caption(r) +
       "; the column 95% CI method names each row's." +
       (boot ? fmt::format(" Bootstrap: {} wild (Rademacher) refits, percentile interval.",
                           r.bootstrap_replicates)
             : ""));
  line("");

  line("## Statistics");
  line("");
  line("| quantity | value |");
  line("|---|---|");
  line(fmt::format("| cost (½ Σ loss of whitened residuals) | {} |", num(r.cost)));
  line(fmt::format("| χ² | {} |", num(r.chi2)));
  line(fmt::format("| residuals | {} |", r.residuals));
  line(fmt::format("| degrees of freedom | {} |", r.dof));
  line(fmt::format("| reduced χ² | {} |", num(r.reduced_chi2)));
  line(fmt::format("| AIC | {} |", num(r.aic)));
  line(fmt::format("| BIC | {} |", num(r.bic)));
  line(fmt::format("| loss | {} |", cell(r.loss)));
  line(fmt::format("| covariance | {} |", r.covariance_scaled_by_reduced_chi2
                                              ? "scaled by the reduced χ²"
                                              : "from absolute σ (not rescaled)"));
  line("");
  if (!r.channel_summaries.empty()) {
    line("| channel | unit | rows | RMSE | R² | scale σ | scale source |");
    line("|---|---|---|---|---|---|---|");
    for (const auto& s : r.channel_summaries)
      line(fmt::format("| {} | {} | {} | {} | {} | {} | {} |", channel_name(s.channel),
                       channel_unit(s.channel), s.rows, num(s.rmse), num(s.r2), num(s.scale),
                       cell(s.scale_source)));
    line("");
    line(
        "RMSE and the scale σ are in the channel's unit. N is the normal load; the newton is "
        "written out.");
    line("");
  }

  line("## Global search and solver");
  line("");
  line(fmt::format("- global search: {}, seed {}, {} evaluations on {} subsampled rows",
                   r.global.algorithm.empty() ? "none" : r.global.algorithm, r.global.seed,
                   r.global.evaluations, r.global.subsample_rows));
  line(fmt::format("- local starts: {}, of which {} reached the best cost{}", r.global.starts,
                   r.global.reached_best,
                   r.global.local_fits_on_subsample
                       ? " (fitted on the subsample; the best was then refined on all rows)"
                       : ""));
  line(fmt::format("- solver: {} iterations, termination {}, {}", r.solver.iterations,
                   r.solver.termination.empty() ? "—" : r.solver.termination,
                   r.solver.converged ? "converged" : "NOT converged"));
  line("");

  line("## Warnings");
  line("");
  if (r.warnings.empty()) line("- none");
  for (const auto& g : group_warnings(r.warnings)) {
    line(fmt::format("**{}** ({}): {}", g.heading, g.warnings.size(), g.severity));
    line("");
    for (std::size_t i : g.warnings) line("- " + one_line(r.warnings[i]));
    line("");
  }
  if (r.warnings.empty()) line("");

  line("## Correlation");
  line("");
  if (r.correlation_names.empty()) {
    line("No free parameter with a standard error.");
  } else {
    std::string head = "| |", rule = "|---|";
    for (const auto& n : r.correlation_names) head += " " + cell(n) + " |", rule += "---|";
    line(head);
    line(rule);
    for (std::size_t i = 0; i < r.correlation_names.size(); ++i) {
      std::string row = "| " + cell(r.correlation_names[i]) + " |";
      for (std::size_t k = 0; k < r.correlation_names.size(); ++k) {
        const bool have = i < r.correlation.size() && k < r.correlation[i].size();
        row += " " + (have ? fixed2(r.correlation[i][k]) : std::string("—")) + " |";
      }
      line(row);
    }
  }
  line("");

  md += provenance_markdown(provenance);

  line("## Plots");
  line("");
  if (plot_files.empty())
    line("No plots were produced (no fitted channel has predictions to plot).");
  for (const auto& f : plot_files) {
    const std::string alt =
        f.size() > 4 && f.compare(f.size() - 4, 4, ".svg") == 0 ? f.substr(0, f.size() - 4) : f;
    line(fmt::format("![{}]({})", alt, f));
    line("");
  }
  return md;
}

}  // namespace frictionid
