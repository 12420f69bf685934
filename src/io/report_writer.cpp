#include "io/report_writer.hpp"

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <tuple>
#include <utility>

#include <fmt/format.h>

#include "io/atomic_file.hpp"
#include "io/gnuplot.hpp"

namespace frictionid {
namespace {

using ojson = nlohmann::ordered_json;
namespace fs = std::filesystem;

// More rows than this are thinned to every k-th row: SVG size and gnuplot time grow per point.
constexpr std::size_t kMaxPlotRows = 4000;  // ~4000 dots already fill an 800x500 plot

// JSON has no NaN/Inf. nlohmann would print null anyway; being explicit keeps the rule visible.
ojson number(double x) {
  return std::isfinite(x) ? ojson(x) : ojson(nullptr);
}
ojson number(const std::optional<double>& x) {
  return x ? number(*x) : ojson(nullptr);
}

const ChannelSummary* find_summary(const FitResult& r, Channel c) {
  for (const auto& s : r.channel_summaries)
    if (s.channel == c) return &s;
  return nullptr;
}

// ---------------------------------------------------------------------------------------------
// Markdown helpers

// %.6g-style; never prints "nan" (the report promises no NaN text).
std::string num(double x) {
  if (std::isnan(x)) return "—";
  if (std::isinf(x)) return x > 0 ? "+inf" : "-inf";
  return fmt::format("{:.6g}", x);
}
std::string num(const std::optional<double>& x) {
  return x ? num(*x) : "—";
}

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

std::string join_channels(const std::vector<Channel>& cs) {
  std::string out;
  for (std::size_t i = 0; i < cs.size(); ++i)
    out += (i ? ", " : "") + std::string(channel_name(cs[i]));
  return out.empty() ? "none" : out;
}

std::string parameter_note(const ParameterEstimate& p) {
  std::vector<std::string> notes;
  if (p.fixed) notes.emplace_back("fixed");
  if (p.at_bound) notes.emplace_back("at bound (stderr not meaningful)");
  if (!p.fixed && !p.at_bound && !p.std_error) notes.emplace_back("not determined");
  std::string out;
  for (std::size_t i = 0; i < notes.size(); ++i) out += (i ? "; " : "") + notes[i];
  return out;
}

std::vector<std::string> default_plot_files(const FitResult& r) {
  std::vector<std::string> files;
  for (Channel c : r.channels) {
    files.push_back(fmt::format("fit_{}.svg", channel_name(c)));
    files.push_back(fmt::format("residuals_{}.svg", channel_name(c)));
  }
  return files;
}

// ---------------------------------------------------------------------------------------------
// Plot helpers

std::string ordinal(std::size_t k) {
  const std::size_t mod100 = k % 100;
  const char* suffix = "th";
  if (mod100 < 11 || mod100 > 13) {
    if (k % 10 == 1) suffix = "st";
    if (k % 10 == 2) suffix = "nd";
    if (k % 10 == 3) suffix = "rd";
  }
  return fmt::format("{}{}", k, suffix);
}

const char* channel_unit(Channel c) {
  return (c == Channel::T_x || c == Channel::T_y) ? "N" : "N m";
}

struct PlotPoint {
  int kind;  // 0: eps <= 0 (left edge), 1: placeable on the log axis, 2: eps = +inf (right edge)
  double eps;
  std::size_t row;
  double measured, fitted, residual;
};

// Appends the gnuplot commands for one channel's two plots to `script` and writes its data file
// into `work`. Returns false (and writes nothing) when the channel has nothing to plot.
bool prepare_channel_plot(const FitResult& r, const Dataset& d, Channel c, const fs::path& work,
                          std::string& script) {
  const int ci = static_cast<int>(c);
  const std::size_t n = d.rows();
  const auto& fitted = r.fitted[ci];
  if (n == 0 || fitted.size() != n || d.value[ci].size() != n || d.present[ci].size() != n)
    return false;

  // Prefer the fitter's eps (the one the model saw); recompute only if it is not there.
  std::vector<double> eps = r.eps;
  if (eps.size() != n) {
    eps.assign(n, std::numeric_limits<double>::quiet_NaN());
    for (std::size_t i = 0; i < n; ++i) {
      if (i >= d.v_x.size() || i >= d.omega.size() || i >= d.R.size()) break;
      const double v = std::hypot(d.v_x[i], i < d.v_y.size() ? d.v_y[i] : 0.0);
      const double u = std::abs(d.omega[i]) * d.R[i];
      if (u > 0)
        eps[i] = v / u;
      else if (v > 0)
        eps[i] = std::numeric_limits<double>::infinity();
    }
  }

  const ChannelSummary* summary = find_summary(r, c);
  const bool channel_scale_ok = summary && std::isfinite(summary->scale) && summary->scale > 0;
  const bool use_sigma = d.has_sigma(c) && d.sigma[ci].size() == n;

  const std::size_t step = n > kMaxPlotRows ? (n + kMaxPlotRows - 1) / kMaxPlotRows : 1;
  std::vector<PlotPoint> pts;
  std::size_t dropped = 0;
  for (std::size_t i = 0; i < n; i += step) {
    if (!d.present[ci][i]) continue;
    const double e = eps[i], m = d.value[ci][i], f = fitted[i];
    if (std::isnan(e) || e == -std::numeric_limits<double>::infinity() || !std::isfinite(m) ||
        !std::isfinite(f)) {
      ++dropped;
      continue;
    }
    double s = channel_scale_ok ? summary->scale : 1.0;
    if (use_sigma && std::isfinite(d.sigma[ci][i]) && d.sigma[ci][i] > 0) s = d.sigma[ci][i];
    const int kind = std::isinf(e) ? 2 : (e <= 0 ? 0 : 1);
    pts.push_back({kind, e, i, m, f, (m - f) / s});
  }
  if (pts.empty()) return false;
  std::sort(pts.begin(), pts.end(), [](const PlotPoint& a, const PlotPoint& b) {
    return std::tie(a.kind, a.eps, a.row) < std::tie(b.kind, b.eps, b.row);
  });

  double emin = std::numeric_limits<double>::infinity(), emax = 0.0;
  bool has_zero = false, has_inf = false;
  for (const auto& p : pts) {
    if (p.kind == 0) has_zero = true;
    if (p.kind == 2) has_inf = true;
    if (p.kind == 1) emin = std::min(emin, p.eps), emax = std::max(emax, p.eps);
  }
  if (emax <= 0) emin = emax = 1.0;  // only edge rows: any decade will do
  // eps = 0 and eps = inf rows sit one decade-ish outside the data, behind a dashed separator.
  const double left = emin / 8, right = emax * 8;

  const std::string name = channel_name(c);
  const std::string data = name + ".dat";
  std::string table = "# x measured fitted residual\n";
  for (const auto& p : pts) {
    const double x = p.kind == 0 ? left : (p.kind == 2 ? right : p.eps);
    table += fmt::format("{:.10g} {:.10g} {:.10g} {:.10g}\n", x, p.measured, p.fitted, p.residual);
  }
  {
    std::ofstream out(work / data, std::ios::binary);
    out << table;
    if (!out) return false;
  }

  std::vector<std::string> notes;
  if (step > 1) notes.push_back(fmt::format("every {} of {} rows plotted", ordinal(step), n));
  if (has_zero && has_inf)
    notes.emplace_back("eps = 0 rows at the left edge, eps = inf rows at the right edge");
  else if (has_zero)
    notes.emplace_back("eps = 0 rows at the left edge");
  else if (has_inf)
    notes.emplace_back("eps = inf rows at the right edge");
  if (dropped > 0)
    notes.push_back(fmt::format("{} rows without a finite eps or prediction dropped", dropped));
  std::string suffix;
  for (const auto& s : notes) suffix += "\\n(" + s + ")";

  std::string axes = fmt::format(
      "set logscale x\nset xrange [{:.10g}:{:.10g}]\nset format x '%g'\nset grid\n"
      "set offsets 0, 0, graph 0.08, graph 0.08\nset key below\nset xlabel 'eps = v/(|omega| R)'\n",
      emin / 16, emax * 16);
  if (has_zero) {
    // A label inside the frame, not an x tic: a tic there would collide with the decade labels.
    axes += "set label 'eps=0' at graph 0.01, graph 0.97 left font ',10'\n";
    axes += fmt::format(
        "set arrow from {0:.10g}, graph 0 to {0:.10g}, graph 1 nohead dt 2 lc rgb 'gray'\n",
        std::sqrt(left * emin));
  }
  if (has_inf) {
    axes += "set label 'eps=inf' at graph 0.99, graph 0.97 right font ',10'\n";
    axes += fmt::format(
        "set arrow from {0:.10g}, graph 0 to {0:.10g}, graph 1 nohead dt 2 lc rgb 'gray'\n",
        std::sqrt(right * emax));
  }

  script += fmt::format("reset\nset output 'fit_{}.svg'\n{}", name, axes);
  script += fmt::format("set ylabel '{} [{}]'\n", name, channel_unit(c));
  script += fmt::format("set title \"{}: measured and fitted{}\"\n", name, suffix);
  script += fmt::format(
      "plot '{0}' using 1:2 with points pt 7 ps 0.5 lc rgb '#1f77b4' title 'measured', \\\n"
      "     '{0}' using 1:3 with points pt 6 ps 0.7 lc rgb '#d62728' title 'fitted'\n",
      data);

  std::string scale_text;
  if (use_sigma)
    scale_text = "sigma";
  else if (channel_scale_ok)
    scale_text = fmt::format("scale ({:.4g} {})", summary->scale, channel_unit(c));
  else
    scale_text = "1 (no scale known)";
  script += fmt::format("reset\nset output 'residuals_{}.svg'\n{}", name, axes);
  script += fmt::format("set ylabel '(measured - fitted) / {}'\n", scale_text);
  script += fmt::format("set title \"{}: whitened residuals{}\"\n", name, suffix);
  script += fmt::format(
      "plot 0 with lines dt 2 lc rgb 'gray' notitle, \\\n"
      "     '{}' using 1:4 with points pt 7 ps 0.5 lc rgb '#1f77b4' title 'residual'\n",
      data);
  return true;
}

// Every plot in one gnuplot run (io/gnuplot.hpp); any failure just drops plots.
std::vector<std::string> write_plots(const fs::path& dir, const FitResult& r, const Dataset& d) {
  return render_svgs(dir, [&](const fs::path& work, std::string& script) {
    std::vector<std::string> expected;
    for (Channel c : r.channels) {
      if (!prepare_channel_plot(r, d, c, work, script)) continue;
      expected.push_back(fmt::format("fit_{}.svg", channel_name(c)));
      expected.push_back(fmt::format("residuals_{}.svg", channel_name(c)));
    }
    return expected;
  });
}

}  // namespace

// ---------------------------------------------------------------------------------------------

nlohmann::ordered_json report_json(const FitResult& r) {
  ojson j = ojson::object();
  j["model"] = r.model;
  j["pressure"] = r.pressure;
  j["rows"] = r.rows;
  ojson channels = ojson::array();
  for (Channel c : r.channels) channels.push_back(channel_name(c));
  j["channels"] = std::move(channels);

  ojson params = ojson::object();
  for (const auto& p : r.parameters) {
    ojson e = ojson::object();
    e["value"] = number(p.value);
    e["stderr"] = number(p.std_error);
    e["ci95"] = p.ci95 ? ojson::array({number((*p.ci95)[0]), number((*p.ci95)[1])}) : ojson();
    e["fixed"] = p.fixed;
    e["at_bound"] = p.at_bound;
    e["initial"] = number(p.initial);
    e["lower"] = number(p.lower);
    e["upper"] = number(p.upper);
    params[p.name] = std::move(e);
  }
  j["parameters"] = std::move(params);

  ojson names = ojson::array();
  for (const auto& n : r.correlation_names) names.push_back(n);
  ojson matrix = ojson::array();
  for (const auto& row : r.correlation) {
    ojson jr = ojson::array();
    for (double x : row) jr.push_back(number(x));
    matrix.push_back(std::move(jr));
  }
  j["correlation"] = {{"names", std::move(names)}, {"matrix", std::move(matrix)}};

  ojson st = ojson::object();
  st["cost"] = number(r.cost);
  st["chi2"] = number(r.chi2);
  st["reduced_chi2"] = number(r.reduced_chi2);
  st["aic"] = number(r.aic);
  st["bic"] = number(r.bic);
  st["dof"] = r.dof;
  st["residuals"] = r.residuals;
  ojson rmse = ojson::object(), r2 = ojson::object(), scales = ojson::object(),
        channel_rows = ojson::object();
  for (const auto& s : r.channel_summaries) {
    const char* name = channel_name(s.channel);
    rmse[name] = number(s.rmse);
    r2[name] = number(s.r2);
    scales[name] = {{"sigma", number(s.scale)}, {"source", s.scale_source}};
    channel_rows[name] = s.rows;
  }
  st["rmse"] = std::move(rmse);
  st["r2"] = std::move(r2);
  st["scales"] = std::move(scales);
  st["channel_rows"] = std::move(channel_rows);  // extra key: rows measuring each channel
  st["covariance_scaled_by_reduced_chi2"] = r.covariance_scaled_by_reduced_chi2;
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
  // Wall time would make two runs of the same fit differ byte-wise: the key stays (design.md)
  // but holds null; the CLI prints the times on stdout.
  so["time_s"] = nullptr;
  so["converged"] = r.solver.converged;
  j["solver"] = std::move(so);

  ojson warnings = ojson::array();
  for (const auto& w : r.warnings) warnings.push_back(w);
  j["warnings"] = std::move(warnings);
  return j;
}

std::string report_markdown(const FitResult& r) {
  return report_markdown(r, default_plot_files(r));
}

std::string report_markdown(const FitResult& r, const std::vector<std::string>& plot_files) {
  std::string md;
  auto line = [&md](const std::string& s) { (md += s) += '\n'; };

  line(fmt::format("# frictionid fit: model {}, pressure {}", one_line(r.model),
                   one_line(r.pressure)));
  line("");
  line(fmt::format("{} rows; fitted channels: {}; loss: {}.", r.rows, join_channels(r.channels),
                   r.loss));
  line("");

  line("## Parameters");
  line("");
  line("| name | value ± stderr | 95% CI | initial | bounds | note |");
  line("|---|---|---|---|---|---|");
  for (const auto& p : r.parameters) {
    std::string value = num(p.value);
    if (p.std_error) value += " ± " + num(p.std_error);
    const std::string ci =
        p.ci95 ? fmt::format("[{}, {}]", num((*p.ci95)[0]), num((*p.ci95)[1])) : "—";
    line(fmt::format("| {} | {} | {} | {} | [{}, {}] | {} |", cell(p.name), value, ci,
                     num(p.initial), num(p.lower), num(p.upper), parameter_note(p)));
  }
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
    line("| channel | rows | RMSE | R² | scale σ | scale source |");
    line("|---|---|---|---|---|---|");
    for (const auto& s : r.channel_summaries)
      line(fmt::format("| {} | {} | {} | {} | {} | {} |", channel_name(s.channel), s.rows,
                       num(s.rmse), num(s.r2), num(s.scale), cell(s.scale_source)));
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
  for (const auto& w : r.warnings) line("- " + one_line(w));
  line("");

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

  line("## Plots");
  line("");
  if (plot_files.empty()) line("No plots were produced (gnuplot not available or failed).");
  for (const auto& f : plot_files) {
    const std::string alt =
        f.size() > 4 && f.compare(f.size() - 4, 4, ".svg") == 0 ? f.substr(0, f.size() - 4) : f;
    line(fmt::format("![{}]({})", alt, f));
    line("");
  }
  return md;
}

std::vector<std::string> write_report(const std::string& dir, const FitResult& r,
                                      const Dataset& d) {
  const fs::path out_dir(dir);
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec || !fs::is_directory(out_dir))
    throw std::runtime_error("cannot create report directory " + dir + ": " +
                             (ec ? ec.message() : std::string("not a directory")));

  std::vector<std::string> written;
  const std::string json = report_json(r).dump(2, ' ', false, ojson::error_handler_t::replace);
  write_file_atomically((out_dir / "report.json").string(), json + "\n");
  written.push_back((out_dir / "report.json").string());

  // Plots before report.md so it links only the plots that exist.
  const std::vector<std::string> plots = write_plots(out_dir, r, d);
  write_file_atomically((out_dir / "report.md").string(), report_markdown(r, plots));
  written.push_back((out_dir / "report.md").string());
  for (const auto& p : plots) written.push_back((out_dir / p).string());
  // A plot of an earlier fit into the same directory (a channel not fitted this time) would
  // sit next to this report as if it belonged to it.
  for (Channel c : kAllChannels)
    for (const char* kind : {"fit", "residuals"}) {
      const std::string name = std::string(kind) + "_" + channel_name(c) + ".svg";
      if (std::find(plots.begin(), plots.end(), name) == plots.end())
        fs::remove(out_dir / name, ec);
    }
  return written;
}

}  // namespace frictionid
