#include <frictionid/io/summary_table.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace frictionid::summary_table_test {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out(1);
  for (char c : line) {
    if (c == ',')
      out.emplace_back();
    else
      out.back().push_back(c);
  }
  return out;
}

// A fit of two parameters listed out of canonical order, one with no standard error.
FitResult two_parameter_fit() {
  FitResult r;
  r.rows = 12;
  ParameterEstimate kappa;
  kappa.name = "kappa";
  kappa.value = 0.1 + 0.2;  // not a short decimal: %.17g must keep every bit
  kappa.std_error = 0.01;
  kappa.ci95 = std::array<double, 2>{0.28, 0.32};
  ParameterEstimate f;
  f.name = "f";
  f.value = 1.0 / 3.0;
  r.parameters = {kappa, f};
  r.cost = 4.5;
  r.reduced_chi2 = kNaN;  // undefined, e.g. no degrees of freedom
  r.warnings = {"one", "two"};
  ChannelSummary c;
  c.channel = Channel::M_z;
  c.noise = NoiseEstimate{NoiseModelKind::Affine, "affine", 0.5, 0.02, 0.0, ""};
  r.channel_summaries = {c};
  return r;
}

TEST(SummaryTable, ColumnsFollowTheContractAndCanonicalParameterOrder) {
  const auto rows = {summary_row("b", two_parameter_fit(), {{"mean_N", 2000.0}})};
  const auto header = cells(lines(summary_csv(rows))[0]);
  const std::vector<std::string> expected = {
      "label",           "status",          "rows",          "f",
      "f_stderr",        "f_ci95_lo",       "f_ci95_hi",     "kappa",
      "kappa_stderr",    "kappa_ci95_lo",   "kappa_ci95_hi", "cost",
      "reduced_chi2",    "warnings",        "error",         "noise_M_z_model",
      "noise_M_z_s_abs", "noise_M_z_s_rel", "mean_N"};
  EXPECT_EQ(header, expected);
}

TEST(SummaryTable, NumbersReadBackBitForBitAndMissingValuesAreEmpty) {
  const auto table = lines(summary_csv({summary_row("b", two_parameter_fit(), {})}));
  const auto row = cells(table[1]);
  EXPECT_EQ(row[0], "b");
  EXPECT_EQ(row[1], "ok");
  EXPECT_EQ(row[2], "12");
  EXPECT_EQ(std::strtod(row[3].c_str(), nullptr), 1.0 / 3.0);
  EXPECT_EQ(row[4], "");  // f has no standard error
  EXPECT_EQ(std::strtod(row[7].c_str(), nullptr), 0.1 + 0.2);
  EXPECT_EQ(row[12], "");  // reduced chi2 NaN: an empty cell, never "nan"
  EXPECT_EQ(row[13], "2");
  EXPECT_EQ(table[1].find("nan"), std::string::npos);
  const auto j = summary_json({summary_row("b", two_parameter_fit(), {})});
  EXPECT_TRUE(j["runs"][0]["reduced_chi2"].is_null());
  EXPECT_TRUE(j["runs"][0]["parameters"]["f"]["stderr"].is_null());
}

TEST(SummaryTable, AFailedRowHasItsErrorQuotedAndNoValues) {
  const std::vector<SummaryRow> rows = {
      failed_summary_row("a", 0, "x.csv:3:2: bad \"number\", expected digits", {}),
      summary_row("b", two_parameter_fit(), {})};
  const auto table = lines(summary_csv(rows));
  EXPECT_EQ(
      table[1].rfind("a,failed,0,,,,,,,,,,,,\"x.csv:3:2: bad \"\"number\"\", expected digits\"", 0),
      0u)
      << table[1];
  const auto j = summary_json(rows);
  EXPECT_EQ(j["failed"], 1);
  EXPECT_EQ(j["runs"][0]["status"], "failed");
}

TEST(SummaryTable, ARowReadBackFromJsonWritesTheSameTable) {
  std::vector<SummaryRow> rows = {
      summary_row("b", two_parameter_fit(),
                  {{"mean_N", 1e-7 / 3}, {"surface", std::string("wet")}}),
      failed_summary_row("c", 5, "diverged", {{"surface", std::string("dry")}})};
  std::vector<SummaryRow> back;
  for (const auto& row : rows) back.push_back(summary_row_from_json(summary_row_json(row)));
  EXPECT_EQ(summary_csv(back), summary_csv(rows));
  EXPECT_EQ(summary_json(back).dump(), summary_json(rows).dump());
}

TEST(SummaryTable, DatasetCovariatesAreMeansOverTheRows) {
  Dataset d;
  d.v_x = {3.0, 0.0};
  d.v_y = {4.0, 1.0};
  d.omega = {-2.0, 4.0};
  d.N = {100.0, 300.0};
  d.R = {0.5, 0.25};
  const auto c = dataset_covariates(d);
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(std::get<double>(c[0].value), 200.0);
  EXPECT_EQ(std::get<double>(c[1].value), 3.0);  // (5 + 1) / 2
  EXPECT_EQ(std::get<double>(c[2].value), 1.0);  // (1 + 1) / 2
}

}  // namespace
}  // namespace frictionid::summary_table_test
