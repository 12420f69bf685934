// What do the tabulated spot integrals (include/frictionid/model/spot_integral_table.hpp) cost
// to build and to evaluate, against the ray integration of spot_integrals.hpp that they replace?
// experiments/README.md, "Contact spots", has the results.
//
//   spot_speed [--repeat N]      # run.sh builds and runs it
//
// For ellipse:0.6 with the Hertz law, rect:0.7 with the parabolic law, the slow ellipses (Hertz
// at q = 0.1, 0.05, 0.01 and 4), table laws of 41 and 201 samples (a modulated Hertz profile)
// and pressure maps (data/footprint_map.csv, 13 x 9, and a random 15 x 15 grid): the table's
// build on 1 and 2 threads (wall and process CPU time, median of N builds; of min(N, 3) for the
// builds over 1 s), its size, and the time of one evaluation of the twelve integrals by the table,
// by SpotIntegrator (rays) and by what gives the table its points (RectStripIntegrator,
// MapStripIntegrator, or for a table law on an ellipse EllipseLawIntegrator through
// SpotPointIntegrator), each the median CPU time of N passes over 256 fixed centres of rotation
// (|c| log-uniform in [0.01, 1000] units of R, any direction), on one thread. The table's
// largest difference over those centres from SpotIntegrator at its fine angular rule (for a
// table law: from the model's points, layers or strips) is printed as a check.
//
//   spot_speed [--repeat N] [--root DIR] [--passes-only] [--maps] [--table-law-aspects]
//              [--map-sizes]
//   # DIR: the repository, for data/footprint_map.csv; --passes-only: the one-pass table only;
//   # --maps: only the two maps' rows of the first table;
//   # --table-law-aspects: only the builds of table laws of 41 and 201 samples on ellipses of
//   # aspect 0.1 to 4 (one build each, one thread);
//   # --map-sizes: only the builds of random maps of 8 x 8 to 44 x 44 samples (one each, one
//   # thread)
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <functional>
#include <memory>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <frictionid/model/pressure_table.hpp>
#include <frictionid/model/spot_integral_table.hpp>
#include <frictionid/model/spot_point_integrator.hpp>
#include <frictionid/model_variant.hpp>

using namespace frictionid::model;

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// CPU time of the calling thread: the evaluations' cost even on a loaded machine.
double thread_cpu() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double process_cpu() {
  return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
}

std::vector<std::array<double, 2>> centres() {
  std::mt19937_64 g(2026);
  auto u01 = [&g] { return static_cast<double>(g() >> 11) * 0x1p-53; };
  std::vector<std::array<double, 2>> out;
  for (int i = 0; i < 256; ++i) {
    const double r = std::pow(10.0, -2.0 + 5.0 * u01()), t = 2.0 * M_PI * u01();
    out.push_back({r * std::cos(t), r * std::sin(t)});
  }
  return out;
}

// Median CPU time of one call over `repeat` passes of the centres, in microseconds.
template <typename F>
double per_call(const F& f, int repeat) {
  const auto cs = centres();
  std::vector<double> passes;
  volatile double sink = 0.0;
  for (int r = 0; r < repeat; ++r) {
    const double t0 = thread_cpu();
    double s = 0.0;
    for (const auto& c : cs) s += f(c[0], c[1]).ey[1];
    passes.push_back(1e6 * (thread_cpu() - t0) / static_cast<double>(cs.size()));
    sink = sink + s;
  }
  return median(passes);
}

// The samples of a map file (x,y,sigma0 rows after a header; # comments), as a PressureMap.
std::shared_ptr<PressureMap> read_map(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::vector<std::array<double, 3>> rows;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#' || line[0] == 'x') continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream s(line);
    std::array<double, 3> r{};
    s >> r[0] >> r[1] >> r[2];
    rows.push_back(r);
  }
  auto m = std::make_shared<PressureMap>();
  for (const auto& r : rows) {
    m->x.push_back(r[0]);
    m->y.push_back(r[1]);
  }
  for (auto* v : {&m->x, &m->y}) {
    std::sort(v->begin(), v->end());
    v->erase(std::unique(v->begin(), v->end()), v->end());
  }
  m->sigma0.assign(m->x.size() * m->y.size(), 0.0);
  for (const auto& r : rows) {
    const auto i = std::lower_bound(m->x.begin(), m->x.end(), r[0]) - m->x.begin();
    const auto j = std::lower_bound(m->y.begin(), m->y.end(), r[1]) - m->y.begin();
    m->sigma0[static_cast<std::size_t>(j) * m->x.size() + static_cast<std::size_t>(i)] = r[2];
  }
  m->source = path;
  return m;
}

// A random n x n grid over [-1.2, 1.2] x [-1, 1] (lines jittered), samples in [0, 1] with one in
// five zero, nonzero on the rim (sigma0 jumps at the edges).
std::shared_ptr<PressureMap> random_map(int n = 15) {
  std::mt19937_64 g(15);
  auto u01 = [&g] { return static_cast<double>(g() >> 11) * 0x1p-53; };
  auto m = std::make_shared<PressureMap>();
  const int last = n - 1;
  for (int i = 0; i < n; ++i) {
    m->x.push_back(-1.2 + 2.4 * (i + (i > 0 && i < last ? 0.3 * (u01() - 0.5) : 0.0)) / last);
    m->y.push_back(-1.0 + 2.0 * (i + (i > 0 && i < last ? 0.3 * (u01() - 0.5) : 0.0)) / last);
  }
  for (int k = 0; k < n * n; ++k) m->sigma0.push_back(u01() < 0.2 ? 0.0 : u01());
  m->source = "random " + std::to_string(n) + " x " + std::to_string(n);
  return m;
}

// A Hertz profile modulated by 1 + 0.3 sin(7 rho), sampled at `samples` equal steps: every
// sample a kink of the interpolant.
PressureLaw<double> sampled_law(int samples) {
  std::vector<double> rho, sigma;
  for (int i = 0; i < samples; ++i) {
    const double r = i / static_cast<double>(samples - 1);
    rho.push_back(r);
    sigma.push_back(std::sqrt(1.0 - r * r) * (1.0 + 0.3 * std::sin(7.0 * r)));
  }
  return PressureLaw<double>::tabulated(std::make_shared<const PressureTable>(rho, sigma));
}

void run(const std::string& name, const ContactSpot& spot, const PressureLaw<double>& law,
         int repeat) {
  const double q = spot.q;
  std::printf("| %s |", name.c_str());
  SpotIntegralTable::Stats stats;
  for (int threads : {1, 2}) {
    std::vector<double> wall, cpu;
    for (int r = 0; r < repeat; ++r) {
      if (r == 3 && median(cpu) > 1.0) break;  // slow builds: the median of three
      const double c0 = process_cpu();
      const auto t0 = std::chrono::steady_clock::now();
      const SpotIntegralTable table(spot, law, q, {}, threads);
      wall.push_back(seconds_since(t0));
      cpu.push_back(process_cpu() - c0);
      stats = table.stats();
    }
    std::printf(" %.2f s (%.2f s CPU) |", median(wall), median(cpu));
  }
  const SpotIntegralTable table(spot, law, q, {}, 2);
  const SpotIntegrator integrate(spot, law, q);
  const double t_table = per_call([&](double x, double y) { return table(x, y); }, 5 * repeat);
  const double t_rays = per_call([&](double x, double y) { return integrate(x, y); }, repeat);
  // What gives the table its points, SpotPointIntegrator's choice: strips on a rectangle or a
  // map, layers of the uniform ellipse for a table law on an ellipse (rays otherwise, timed
  // above).
  const SpotPointIntegrator points(spot, law, q);
  const bool by_points = law.kind == PressureKind::Table;
  std::string strips = "–";
  if (spot.kind == SpotKind::Rect || spot.kind == SpotKind::Map || by_points) {
    char buf[32];
    std::snprintf(buf, sizeof buf, spot.kind == SpotKind::Ellipse ? "%.1f us (layers)" : "%.1f us",
                  per_call([&](double x, double y) { return points(x, y); }, repeat));
    strips = buf;
  }
  // The check, relative to A0: the table against the rays at their fine angular rule, or for a
  // table law (whose rays keep at most 64 samples as cuts) against those points, exact for any
  // number of samples.
  // (The ring's rim integral takes a tanh-sinh rule of step 1/128 along the rim.)
  static const std::vector<QuadratureNode> rim = make_tanh_sinh_rule(1.0 / 128.0, 1e-30);
  const bool ring = law.kind == PressureKind::Ring;
  const SpotIntegrator fine(spot, law, q,
                            SpotRules{&radial_rule(), ring ? &rim : &fine_rule(), false, false});
  const double A0 = spot_moments(spot, law_moments(law), q).A0;
  double worst = 0.0;
  for (const auto& c : centres()) {
    const SpotIntegrals a = table(c[0], c[1]),
                        b = by_points ? points(c[0], c[1]) : fine(c[0], c[1]);
    for (std::size_t w = 0; w < 3; ++w)
      worst = std::max({worst, std::fabs(a.ex[w] - b.ex[w]), std::fabs(a.ey[w] - b.ey[w]),
                        std::fabs(a.x_ey[w] - b.x_ey[w]), std::fabs(a.y_ex[w] - b.y_ex[w])});
  }
  std::printf(" %zu | %zu | %.0f kB | **%.2f us** | %.0f us | %s | %.0e |\n", stats.points,
              stats.pieces, stats.coefficients * 12 * 8 / 1e3, t_table, t_rays, strips.c_str(),
              worst / A0);
}

// One pass over n rows (eval, generate, a fit's row cache), CPU time on one thread: integrating
// every row (SpotPointIntegrator), always building the table and reading it, and the rule of
// model_variant.hpp (spot_table_budget: a build with a budget of as many points as the rows cost,
// abandoned before it would exceed it, and the rows then integrated). The rows are the
// 256 centres of rotation above, whose cost per row is measured; the first two columns are that
// cost times n, and the build's time plus n readings. The rule's column is its attempt, measured,
// plus n readings or integrations at the measured rates.
void pass(const std::string& name, const ContactSpot& spot, const PressureLaw<double>& law,
          int repeat) {
  const double q = spot.q;
  const SpotPointIntegrator points(spot, law, q);
  const double row = 1e-6 * per_call([&](double x, double y) { return points(x, y); }, repeat);
  const double c0 = process_cpu();
  const SpotIntegralTable table(spot, law, q, {}, 1);
  const double build = process_cpu() - c0;
  const double read = 1e-6 * per_call([&](double x, double y) { return table(x, y); }, repeat);
  for (std::size_t n : {2000, 10000, 50000, 200000}) {
    const double integrate = static_cast<double>(n) * row,
                 tabulate = build + static_cast<double>(n) * read;
    const std::size_t budget = frictionid::spot_table_budget(spot, law, n);
    bool built = false;
    const double a0 = process_cpu();
    if (budget > 0) {
      try {
        const SpotIntegralTable attempt(spot, law, q, {}, 1, budget);
        built = true;
      } catch (const SpotTableOverBudget&) {
      }
    }
    const double rule = process_cpu() - a0 + static_cast<double>(n) * (built ? read : row);
    std::printf("| %s | %zu | %.2f s | %.2f s | %.2f s (%s) | %.2f |\n", name.c_str(), n, integrate,
                tabulate, rule, built ? "table" : "integrated",
                rule / std::min(integrate, tabulate));
  }
}

// One build on one thread of a table law of 41 and of 201 samples on ellipses of aspect 0.1 to 4:
// CPU time and points.
void table_law_aspects() {
  std::printf("| table law on an ellipse | q = 0.1 | 0.3 | 0.5 | 0.7 | 1 | 2 | 4 |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|\n");
  for (int samples : {41, 201}) {
    std::printf("| %d samples |", samples);
    for (double q : {0.1, 0.3, 0.5, 0.7, 1.0, 2.0, 4.0}) {
      const double c0 = process_cpu();
      const SpotIntegralTable table(ContactSpot::ellipse(q), sampled_law(samples), q, {}, 1);
      std::printf(" %.2f s, %zu |", process_cpu() - c0, table.stats().points);
      std::fflush(stdout);
    }
    std::printf("\n");
  }
}

// One build on one thread of random maps of 8 x 8 to 30 x 30 samples: CPU time and points.
void map_sizes() {
  std::printf("| random map | build, 1 thread (CPU) | points | per point |\n");
  std::printf("|---|---:|---:|---:|\n");
  for (int n : {8, 15, 20, 30, 44}) {
    const double c0 = process_cpu();
    const SpotIntegralTable table(ContactSpot::pressure_map(random_map(n)),
                                  PressureLaw<double>::uniform(), 1.0, {}, 1);
    const double t = process_cpu() - c0;
    std::printf("| %d x %d | %.2f s | %zu | %.1f us |\n", n, n, t, table.stats().points,
                1e6 * t / static_cast<double>(table.stats().points));
    std::fflush(stdout);
  }
}

}  // namespace

int main(int argc, char** argv) {
  int repeat = 5;
  bool passes_only = false, maps_only = false;
  std::string root = ".";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--repeat" && i + 1 < argc) {
      repeat = std::max(1, std::atoi(argv[++i]));
    } else if (a == "--passes-only") {
      passes_only = true;
    } else if (a == "--maps") {
      maps_only = true;
    } else if (a == "--table-law-aspects") {
      table_law_aspects();
      return 0;
    } else if (a == "--map-sizes") {
      map_sizes();
      return 0;
    } else if (a == "--root" && i + 1 < argc) {
      root = argv[++i];
    } else {
      std::fprintf(stderr,
                   "usage: spot_speed [--repeat N] [--root DIR] [--passes-only] [--maps] "
                   "[--table-law-aspects] [--map-sizes]\n");
      return 2;
    }
  }
  if (!passes_only) {
    std::printf(
        "| spot, law | build, 1 thread | build, 2 threads | points | pieces | size | table | "
        "SpotIntegrator (rays) | the build's points (strips, layers) | table - reference (of A0) "
        "|\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  }
  if (!passes_only && !maps_only) {
    run("ellipse:0.6, hertz", ContactSpot::ellipse(0.6), PressureLaw<double>::hertz(), repeat);
    run("rect:0.7, parabolic", ContactSpot::rect(0.7), PressureLaw<double>::parabolic(), repeat);
    run("ellipse:0.1, hertz", ContactSpot::ellipse(0.1), PressureLaw<double>::hertz(), repeat);
    run("ellipse:4, hertz", ContactSpot::ellipse(4.0), PressureLaw<double>::hertz(), repeat);
    run("ellipse:0.05, hertz", ContactSpot::ellipse(0.05), PressureLaw<double>::hertz(), repeat);
    run("ellipse:0.01, hertz", ContactSpot::ellipse(0.01), PressureLaw<double>::hertz(), repeat);
    run("ellipse:0.1, power:1.7", ContactSpot::ellipse(0.1), PressureLaw<double>::power(1.7),
        repeat);
    run("ellipse:0.1, annulus:0.5", ContactSpot::ellipse(0.1), PressureLaw<double>::annulus(0.5),
        repeat);
    run("ellipse:0.1, ring", ContactSpot::ellipse(0.1), PressureLaw<double>::ring(), repeat);
    run("ellipse:0.7, table of 41 samples", ContactSpot::ellipse(0.7), sampled_law(41), repeat);
    run("ellipse:0.7, table of 201 samples", ContactSpot::ellipse(0.7), sampled_law(201), repeat);
    run("rect:0.7, table of 201 samples", ContactSpot::rect(0.7), sampled_law(201), repeat);
  }
  if (!passes_only) {
    run("map, footprint 13 x 9",
        ContactSpot::pressure_map(read_map(root + "/data/footprint_map.csv")),
        PressureLaw<double>::uniform(), repeat);
    run("map, random 15 x 15", ContactSpot::pressure_map(random_map()),
        PressureLaw<double>::uniform(), repeat);
  }
  if (maps_only) return 0;
  std::printf(
      "\n| one pass over n rows | n | integrate every row | always tabulate | the rule | the rule "
      "/ the better |\n");
  std::printf("|---|---:|---:|---:|---:|---:|\n");
  pass("ellipse:0.6, hertz", ContactSpot::ellipse(0.6), PressureLaw<double>::hertz(), repeat);
  pass("ellipse:0.05, hertz", ContactSpot::ellipse(0.05), PressureLaw<double>::hertz(), repeat);
  pass("ellipse:0.1, annulus:0.5", ContactSpot::ellipse(0.1), PressureLaw<double>::annulus(0.5),
       repeat);
  pass("ellipse:0.7, table of 201 samples", ContactSpot::ellipse(0.7), sampled_law(201), repeat);
  pass("rect:0.7, table of 201 samples", ContactSpot::rect(0.7), sampled_law(201), repeat);
  pass("map, footprint 13 x 9",
       ContactSpot::pressure_map(read_map(root + "/data/footprint_map.csv")),
       PressureLaw<double>::uniform(), repeat);
  return 0;
}
