#include <frictionid/io/compare_report.hpp>

#include <gtest/gtest.h>

#include <string>

namespace frictionid {
namespace {

FitResult fit_with(const std::string& model,
                   const std::vector<std::pair<std::string, double>>& params) {
  FitResult r;
  r.model = model;
  for (const auto& [name, value] : params) {
    ParameterEstimate p;
    p.name = name;
    p.value = value;
    r.parameters.push_back(p);
  }
  return r;
}

bool has_note(const std::vector<std::string>& notes, const std::string& a, const std::string& b) {
  for (const auto& n : notes)
    if (n.find(a) != std::string::npos && n.find(b) != std::string::npos) return true;
  return false;
}

// Every freely fitted closed-form coefficient gets a sentence: close to the value the exact
// fit's pressure shape implies (within 5 %), or a curve-fit constant that absorbed shape error.
TEST(CompareReport, EveryFittedCoefficientIsSetAgainstTheOneTheExactFitImplies) {
  ModelComparison c;
  c.fits = {fit_with("seed", {{"a", 0.73}, {"b", 37.5}, {"m", 7.6}}),
            fit_with("corrected", {{"a", 0.72}, {"b_tilde", 3.0}, {"m", 7.6}, {"p0", 0.2}}),
            fit_with("exact", {{"f", 0.9}})};
  c.implied_by_exact = {{"a", 0.72}, {"b", 25.0}, {"m", 7.58}, {"b_tilde", 3.0}, {"p0", 0.29}};
  const auto notes = coefficient_notes(c);
  EXPECT_EQ(notes.size(), 7u);
  EXPECT_TRUE(has_note(notes, "seed: fitted a", "agrees within 5%"));
  EXPECT_TRUE(has_note(notes, "seed: fitted b", "differs by +50%"));
  EXPECT_TRUE(has_note(notes, "corrected: fitted p0", "differs by -31%"));
  EXPECT_TRUE(has_note(notes, "corrected: fitted b_tilde", "agrees within 5%"));
  c.implied_by_exact.clear();
  EXPECT_TRUE(coefficient_notes(c).empty());
}

}  // namespace
}  // namespace frictionid
