// Does the two-term noise estimator (noise_model.cpp, docs/physics.md §8.10) reach the
// likelihood maximum on every dataset? For R replicates it draws a noise law and a sample,
// estimates the noise with estimate_channel_noise, and compares -2 ln L at the estimate with a
// brute-force maximisation (tests/support/noise_brute_force.hpp). experiments/README.md, "Two-term
// noise estimator against brute force", has the results.
//
//   noise_stress [--replicates R] [--form affine|additive] [--output FILE]
//
// The replicates: tests/support/noise_stress_sample.hpp.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <frictionid/fit_settings.hpp>
#include "identify/noise_model.hpp"
#include "support/noise_brute_force.hpp"
#include "support/noise_stress_sample.hpp"

using namespace frictionid;
using frictionid::test::TwoTerm;

int main(int argc, char** argv) {
  int replicates = 1000;
  std::string form_name = "affine", output = "noise_stress.csv";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (i + 1 >= argc) {
      std::cerr << a << " needs a value\n";
      return 2;
    }
    const std::string v = argv[++i];
    if (a == "--replicates")
      replicates = std::stoi(v);
    else if (a == "--form")
      form_name = v;
    else if (a == "--output")
      output = v;
    else {
      std::cerr << "unknown option " << a << "\n";
      return 2;
    }
  }
  if (form_name != "affine" && form_name != "additive") {
    std::cerr << "--form must be affine or additive\n";
    return 2;
  }
  const TwoTerm form = form_name == "affine" ? TwoTerm::Affine : TwoTerm::Additive;
  const NoiseModelKind kind = *parse_noise_model_kind(form_name);

  std::ofstream csv(output);
  csv << "replicate,design,rows,s_abs,s_rel,est_s_abs,est_s_rel,neg2_loglik,brute_force,gap,"
         "note\n";
  int failures = 0;
  double worst = -HUGE_VAL, estimator_seconds = 0.0;
  for (int r = 0; r < replicates; ++r) {
    const test::StressSample s = test::stress_sample(r, form);
    const auto t0 = std::chrono::steady_clock::now();
    const ChannelNoise n = estimate_channel_noise(s.y, s.e, kind);
    estimator_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double est = test::two_term_neg2_loglik(form, n.s_abs, n.s_rel, s.y, s.e);
    const auto bf = test::brute_force_maximum(form, s.y, s.e);
    const double gap = est - bf.neg2_loglik;
    // A miss: the estimate's -2 ln L above the brute force's by more than rounding.
    const bool miss = gap > 1e-6 + 1e-9 * std::fabs(bf.neg2_loglik);
    failures += miss;
    worst = std::max(worst, gap);
    char line[512];
    std::snprintf(line, sizeof line, "%d,%d,%zu,%.6g,%.6g,%.10g,%.10g,%.12g,%.12g,%.3g,%s\n", r,
                  s.design, s.y.size(), s.s_abs, s.s_rel, n.s_abs, n.s_rel, est, bf.neg2_loglik,
                  gap, n.problem.c_str());
    csv << line;
  }
  std::printf(
      "%s: %d replicates, %d below the brute-force maximum (gap > 1e-6 + 1e-9 |-2 ln L|), "
      "largest gap %.3g, estimator %.3f ms per sample\n",
      form_name.c_str(), replicates, failures, worst, 1e3 * estimator_seconds / replicates);
  return 0;
}
