#include "app/shimmy_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

#include <fmt/format.h>

#include <frictionid/io/input_error.hpp>
#include "app/shimmy.hpp"
#include "io/html_page.hpp"
#include "io/json_number.hpp"
#include "io/palette.hpp"
#include "io/svg_plot.hpp"

namespace frictionid::app {

namespace {

// The wheel parameters a 2-D sweep can vary, and where they live.
double* sweep_target(model::ShimmyWheel& w, const std::string& name) {
  if (name == "yaw-damping") return &w.c_psi;
  if (name == "caster") return &w.caster;
  if (name == "yaw-stiffness") return &w.k_psi;
  if (name == "lateral-damping") return &w.c_y;
  return nullptr;
}

bool is_shimmy(model::ShimmyOutcome o) {
  return o == model::ShimmyOutcome::LimitCycle || o == model::ShimmyOutcome::Growing;
}

}  // namespace

SweepRange parse_sweep_range(const std::string& option, const std::string& text) {
  const auto bad = [&](const std::string& why) {
    return InputError(option + " '" + text + "': " + why);
  };
  const auto c1 = text.find(':');
  const auto c2 = c1 == std::string::npos ? c1 : text.find(':', c1 + 1);
  if (c2 == std::string::npos) throw bad("expected A:B:N");
  SweepRange r;
  try {
    std::size_t used = 0;
    const std::string a = text.substr(0, c1), b = text.substr(c1 + 1, c2 - c1 - 1),
                      n = text.substr(c2 + 1);
    r.a = std::stod(a, &used);
    if (used != a.size()) throw bad("A is not a number");
    r.b = std::stod(b, &used);
    if (used != b.size()) throw bad("B is not a number");
    const long count = std::stol(n, &used);
    if (used != n.size() || count < 2 || count > 10000)
      throw bad("N must be a whole number from 2 to 10000");
    r.n = static_cast<int>(count);
  } catch (const std::logic_error&) {
    throw bad("expected A:B:N with numbers A < B and a count N >= 2");
  }
  if (!std::isfinite(r.a) || !std::isfinite(r.b) || !(r.a < r.b)) throw bad("needs A < B");
  return r;
}

SweepResult shimmy_sweep(const ShimmyRequest& r, const std::function<void(int, int)>& progress,
                         const TableProgress& table_progress) {
  SweepResult out;
  const SweepRange speeds = parse_sweep_range("--speed-sweep", r.speed_sweep);
  if (!(speeds.a > 0.0)) throw InputError("--speed-sweep: the speeds must be > 0");
  SweepRange params{0.0, 0.0, 1};
  if (!r.sweep_param.empty()) {
    const auto colon = r.sweep_param.find(':');
    out.param_name = r.sweep_param.substr(0, colon);
    model::ShimmyWheel probe;
    if (colon == std::string::npos || !sweep_target(probe, out.param_name))
      throw InputError("--sweep-param '" + r.sweep_param +
                       "': expected yaw-damping, caster, yaw-stiffness or lateral-damping, then "
                       ":A:B:N");
    params = parse_sweep_range("--sweep-param", r.sweep_param.substr(colon + 1));
    if (out.param_name != "caster" && params.a < 0.0)
      throw InputError("--sweep-param " + out.param_name + " must be >= 0");
  }
  ShimmyRequest base = r;
  base.output.clear();
  base.trajectory = false;
  const ShimmyCase c(base, table_progress);
  model::ShimmySettings set = c.settings();
  set.record = false;
  set.stop_at_limit_cycle = true;
  out.onset_tol = r.onset_tol > 0.0 ? r.onset_tol : 1e-3 * (speeds.b - speeds.a);
  const int total = speeds.n * params.n;
  int done = 0;
  const auto classify = [&](model::ShimmyWheel w, double V, const model::ShimmyStart& start) {
    w.V = V;
    return c.run(w, start, set, {});
  };
  for (int j = 0; j < params.n; ++j) {
    model::ShimmyWheel w = c.wheel();
    const double p = out.param_name.empty() ? 0.0 : params.at(j);
    if (!out.param_name.empty()) *sweep_target(w, out.param_name) = p;
    model::ShimmyStart start = c.start();
    std::vector<SweepPoint> row;
    for (int i = 0; i < speeds.n; ++i) {
      const double V = speeds.at(i);
      const model::ShimmyRun run = classify(w, V, start);
      SweepPoint pt{V, p, model::outcome_name(run.outcome), "", 0.0, 0.0, is_shimmy(run.outcome)};
      if (run.outcome == model::ShimmyOutcome::Duration)
        pt.detail = model::duration_detail_name(run.cycle.detail);
      if (pt.shimmy) {
        pt.amplitude = run.cycle.amplitude;
        pt.frequency = run.cycle.frequency;
      }
      // Continuation: the next speed starts on this limit cycle, else from the request's start.
      start = c.start();
      if (run.outcome == model::ShimmyOutcome::LimitCycle)
        start = {run.final[model::kSY], run.final[model::kSYDot], run.final[model::kSPsi],
                 run.final[model::kSPsiDot]};
      row.push_back(pt);
      if (progress) progress(++done, total);
    }
    // Onsets between neighbours of different stability, by bisection from the request's start.
    for (int i = 0; i + 1 < speeds.n; ++i) {
      if (row[i].shimmy == row[i + 1].shimmy) continue;
      double lo = row[i].speed, hi = row[i + 1].speed;
      const bool low_shimmy = row[i].shimmy;
      while (hi - lo > out.onset_tol) {
        const double mid = 0.5 * (lo + hi);
        const bool s = is_shimmy(classify(w, mid, c.start()).outcome);
        (s == low_shimmy ? lo : hi) = mid;
      }
      out.onsets.push_back({p, 0.5 * (lo + hi), lo, hi, !low_shimmy});
    }
    out.points.insert(out.points.end(), row.begin(), row.end());
  }
  nlohmann::ordered_json j = c.description(c.wheel());
  j.erase("speed");
  j["speed_sweep"] = {{"from", speeds.a}, {"to", speeds.b}, {"count", speeds.n}};
  if (!out.param_name.empty())
    j["sweep_param"] = {
        {"name", out.param_name}, {"from", params.a}, {"to", params.b}, {"count", params.n}};
  nlohmann::ordered_json pts = nlohmann::ordered_json::array();
  for (const auto& p : out.points) {
    nlohmann::ordered_json e{{"speed", p.speed}};
    if (!out.param_name.empty()) e[out.param_name] = p.param;
    e["outcome"] = p.outcome;
    if (!p.detail.empty()) e["detail"] = p.detail;
    e["amplitude"] = p.amplitude;
    e["frequency"] = p.frequency;
    pts.push_back(std::move(e));
  }
  j["points"] = std::move(pts);
  nlohmann::ordered_json ons = nlohmann::ordered_json::array();
  for (const auto& o : out.onsets) {
    nlohmann::ordered_json e;
    if (!out.param_name.empty()) e[out.param_name] = o.param;
    e["speed"] = o.speed;
    e["bracket"] = {o.lo, o.hi};
    e["shimmy_above"] = o.shimmy_above;
    ons.push_back(std::move(e));
  }
  j["onset_tolerance"] = out.onset_tol;
  j["onsets"] = std::move(ons);
  out.summary = std::move(j);
  return out;
}

std::string sweep_csv(const SweepResult& s) {
  std::string out = s.param_name.empty() ? "V,outcome,amplitude,frequency\n"
                                         : "V," + s.param_name + ",outcome,amplitude,frequency\n";
  for (const auto& p : s.points) {
    if (s.param_name.empty())
      fmt::format_to(std::back_inserter(out), "{:.17g},{},{:.17g},{:.17g}\n", p.speed, p.outcome,
                     p.amplitude, p.frequency);
    else
      fmt::format_to(std::back_inserter(out), "{:.17g},{:.17g},{},{:.17g},{:.17g}\n", p.speed,
                     p.param, p.outcome, p.amplitude, p.frequency);
  }
  return out;
}

std::string sweep_html(const SweepResult& s, const std::string& title) {
  svg::Plot plot;
  plot.title = "Shimmy amplitude of psi against speed";
  plot.notes.push_back(
      "filled: limit cycle or growing (shimmy); amplitude 0: stable (rest or "
      "decaying); dashed: onset speeds (bisection to " +
      svg::tick_label(s.onset_tol) + " m/s)");
  plot.x_label = "V [m/s]";
  plot.y_label = "amplitude of psi [rad]";
  plot.y_reference = 0.0;
  std::vector<double> values;
  for (const auto& p : s.points)
    if (values.empty() || values.back() != p.param) values.push_back(p.param);
  for (std::size_t k = 0; k < values.size(); ++k) {
    svg::Series line, stable;
    const std::string color = palette::series(k);
    line.label =
        s.param_name.empty() ? "shimmy" : s.param_name + " = " + svg::tick_label(values[k]);
    line.color = color;
    line.mark = svg::Mark::Line;
    stable.color = palette::kBackdrop;
    stable.label = k == 0 ? "stable" : "";
    for (const auto& p : s.points) {
      if (p.param != values[k]) continue;
      line.x.push_back(p.speed);
      line.y.push_back(p.amplitude);
      if (!p.shimmy) {
        stable.x.push_back(p.speed);
        stable.y.push_back(0.0);
      }
    }
    svg::Series dots = line;
    dots.mark = svg::Mark::Dots;
    dots.label.clear();
    dots.x.clear();
    dots.y.clear();
    for (const auto& p : s.points)
      if (p.param == values[k] && p.shimmy) {
        dots.x.push_back(p.speed);
        dots.y.push_back(p.amplitude);
      }
    plot.series.push_back(std::move(line));
    plot.series.push_back(std::move(dots));
    plot.series.push_back(std::move(stable));
  }
  for (const auto& o : s.onsets)
    plot.x_markers.push_back({o.speed, "onset " + svg::tick_label(o.speed)});
  std::string page = html::page_start(svg::escape(title));
  // In a plot figure, as on the reports: at least 402 px wide on a narrow screen (10 px text),
  // scrolling in its box rather than widening the page.
  page += "<h1>" + svg::escape(title) + "</h1>\n<figure class=\"plot\">\n" + svg::render(plot) +
          "\n</figure>\n";
  page += "<h2>Onset speeds</h2>\n<table><tr>";
  if (!s.param_name.empty()) page += "<th>" + svg::escape(s.param_name) + "</th>";
  page += "<th>V [m/s]</th><th>bracket</th><th>shimmy</th></tr>\n";
  for (const auto& o : s.onsets) {
    page += "<tr>";
    if (!s.param_name.empty()) page += html::num_cell(o.param);
    page += html::num_cell(o.speed) + "<td>" + svg::tick_label(o.lo) + " to " +
            svg::tick_label(o.hi) + "</td><td>" + (o.shimmy_above ? "above" : "below") +
            "</td></tr>\n";
  }
  page += "</table>\n";
  if (!s.param_name.empty()) {
    // The 2-D map: one row per parameter value, one column per speed; shimmy cells shaded.
    std::vector<double> speeds;
    for (const auto& p : s.points)
      if (p.param == values.front()) speeds.push_back(p.speed);
    page +=
        "<h2>Map</h2>\n<p>Amplitude of psi [rad]; shaded: shimmy (limit cycle or growing), "
        "blank: stable.</p>\n<table><tr><th>" +
        svg::escape(s.param_name) + " \\ V [m/s]</th>";
    for (double v : speeds) page += "<th>" + svg::tick_label(v) + "</th>";
    page += "</tr>\n";
    for (double value : values) {
      page += "<tr><th>" + svg::tick_label(value) + "</th>";
      for (const auto& p : s.points) {
        if (p.param != value) continue;
        page += p.shimmy
                    ? "<td style=\"background:#f4b6b6\">" + svg::tick_label(p.amplitude) + "</td>"
                    : std::string("<td></td>");
      }
      page += "</tr>\n";
    }
    page += "</table>\n";
  }
  page += "<h2>Runs</h2>\n<table><tr><th>V [m/s]</th>";
  if (!s.param_name.empty()) page += "<th>" + svg::escape(s.param_name) + "</th>";
  page += "<th>outcome</th><th>amplitude [rad]</th><th>frequency [Hz]</th></tr>\n";
  for (const auto& p : s.points) {
    page += "<tr>" + html::num_cell(p.speed);
    if (!s.param_name.empty()) page += html::num_cell(p.param);
    page += "<td>" + p.outcome + (p.detail.empty() ? "" : " (" + p.detail + ")") + "</td>" +
            html::num_cell(p.amplitude) + html::num_cell(p.frequency) + "</tr>\n";
  }
  page += "</table>\n" + html::page_end();
  return page;
}

}  // namespace frictionid::app
