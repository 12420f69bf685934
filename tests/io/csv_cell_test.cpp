// Formula neutralising in the CSV files frictionid writes (OWASP "CSV injection"): a text cell
// that Excel or LibreOffice would evaluate is written with a leading apostrophe; a number stays
// a number.
#include "io/csv_cell.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <frictionid/io/summary_table.hpp>

namespace frictionid::csv_cell_test {
namespace {

TEST(CsvCell, ACellThatStartsAFormulaGetsALeadingApostrophe) {
  EXPECT_EQ(csv_cell("=1+2"), "'=1+2");
  EXPECT_EQ(csv_cell("@SUM(A1)"), "'@SUM(A1)");
  EXPECT_EQ(csv_cell("+cmd"), "'+cmd");
  EXPECT_EQ(csv_cell("-2+3"), "'-2+3");
  EXPECT_EQ(csv_cell("=HYPERLINK(\"http://x\",\"y\")"),
            "\"'=HYPERLINK(\"\"http://x\"\",\"\"y\"\")\"");
  EXPECT_EQ(csv_cell("\t=1"), "'\t=1");
  EXPECT_EQ(csv_cell("\r=1"), "\"'\r=1\"");
  EXPECT_EQ(csv_cell("-"), "'-");
}

TEST(CsvCell, NumbersStayNumbers) {
  for (const char* number : {"-2.5", "+1e3", "-0", "-1.2345678901234567e-300", "3"})
    EXPECT_EQ(csv_cell(number), number);
}

TEST(CsvCell, OtherCellsAreQuotedOnlyWhereRfc4180NeedsIt) {
  EXPECT_EQ(csv_cell("plain"), "plain");
  EXPECT_EQ(csv_cell(""), "");
  EXPECT_EQ(csv_cell("a,b"), "\"a,b\"");
  EXPECT_EQ(csv_cell("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csv_cell("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(csv_cell(" padded "), "\" padded \"");
  EXPECT_EQ(csv_cell("a=1"), "a=1");  // a formula starts at the first character only
}

TEST(SummaryCsv, FormulaLabelsAndTextCellsAreNeutralisedNumbersStayNumbers) {
  SummaryRow row;
  row.label = "=1+2";
  row.ok = true;
  row.rows = 10;
  SummaryParameter f;
  f.name = "f";
  f.value = -2.5;
  row.parameters = {f};
  row.covariates = {{"@x", std::string("+cmd")}, {"load", std::string("-1500")}};
  const std::string csv = summary_csv({row, failed_summary_row("-2+3", 0, "-bad", {})});
  EXPECT_NE(csv.find(",'@x,load\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\n'=1+2,ok,10,-2.5,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",'+cmd,-1500\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\n'-2+3,failed,0,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",'-bad,"), std::string::npos) << csv;
}

}  // namespace
}  // namespace frictionid::csv_cell_test
