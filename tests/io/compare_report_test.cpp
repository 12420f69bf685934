#include <frictionid/io/compare_report.hpp>

#include <gtest/gtest.h>

#include <string>

namespace frictionid::compare_report_test {
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
}  // namespace frictionid::compare_report_test

namespace frictionid::compare_report_test {
namespace {

ModelComparison circle_and_ellipse() {
  ModelComparison c;
  c.fits = {fit_with("exact", {{"f", 0.9}}), fit_with("exact", {{"f", 0.91}, {"q", 0.7}})};
  c.fits[0].aic = 10.0;
  c.fits[1].aic = 4.0;
  c.fits[0].bic = 12.0;
  c.fits[1].bic = 7.0;
  c.delta_aic = {6.0, 0.0};
  c.delta_bic = {5.0, 0.0};
  c.preferred_by_aic = c.preferred_by_bic = "exact";  // what compare_models names: the model
  c.residual_autocorrelation.resize(2);
  return c;
}

// The same model on two spots: compare.json keeps the model's name and states the spot; the
// preferred fit is named MODEL@SPOT so that it is told apart from the circle's.
TEST(CompareReport, FitsOnOtherSpotsStateTheirContactAndArePreferredByVariantName) {
  const ModelComparison c = circle_and_ellipse();
  const auto j = compare_json(c, {}, {"circle", "ellipse:0.7"});
  EXPECT_EQ(j["models"][0]["model"], "exact");
  EXPECT_FALSE(j["models"][0].contains("contact"));
  EXPECT_EQ(j["models"][1]["model"], "exact");
  EXPECT_EQ(j["models"][1]["contact"], "ellipse:0.7");
  EXPECT_EQ(j["preferred_by_aic"], "exact@ellipse:0.7");
  EXPECT_EQ(j["preferred_by_bic"], "exact@ellipse:0.7");
  const std::string md = compare_markdown(c, {}, {}, {"circle", "ellipse:0.7"});
  EXPECT_NE(md.find("| exact@ellipse:0.7 |"), std::string::npos) << md;
  EXPECT_NE(md.find("[exact@ellipse:0.7](exact@ellipse_0.7/report.md)"), std::string::npos) << md;
}

// Without spots (or on the circle alone) a comparison is what it always was.
TEST(CompareReport, AComparisonOnTheCircleAloneIsUnchanged) {
  const ModelComparison c = circle_and_ellipse();
  EXPECT_EQ(compare_json(c, {}, {"circle", "circle"}), compare_json(c));
  EXPECT_EQ(compare_markdown(c, {}, {}, {"circle", "circle"}), compare_markdown(c, {}));
  EXPECT_EQ(compare_json(c)["preferred_by_aic"], "exact");
}

TEST(CompareReport, AVariantsDirectoryKeepsOnlySafeCharacters) {
  EXPECT_EQ(compare_variant_directory("exact"), "exact");
  EXPECT_EQ(compare_variant_directory("exact@ellipse:0.7"), "exact@ellipse_0.7");
  EXPECT_EQ(compare_variant_directory("exact@map:../maps/foot print.csv"),
            "exact@map_.._maps_foot_print.csv");
}

}  // namespace
}  // namespace frictionid::compare_report_test
