// The LAW argument: the named laws annulus:B and ring, their bad spellings, their labels, and
// the table step syntax (two rows with the same rho) read from a file.
#include <frictionid/io/pressure_law_reader.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include <frictionid/io/input_error.hpp>

namespace frictionid::pressure_law_reader_test {
namespace {

TEST(PressureLawReader, AnnulusTakesItsInnerRadius) {
  const auto law = parse_pressure_law("annulus:0.3");
  EXPECT_EQ(law.kind, model::PressureKind::Annulus);
  EXPECT_EQ(law.inner_radius(), 0.3);
  EXPECT_EQ(parse_pressure_law("annulus:0").inner_radius(), 0.0);
}

TEST(PressureLawReader, RingIsANamedLaw) {
  EXPECT_EQ(parse_pressure_law("ring").kind, model::PressureKind::Ring);
}

std::string message_of(const std::string& spec) {
  try {
    parse_pressure_law(spec);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(PressureLawReader, RejectsAnInnerRadiusOutsideZeroToOne) {
  for (const char* spec : {"annulus:1", "annulus:-0.1", "annulus:1.5"})
    EXPECT_NE(message_of(spec).find(std::string("pressure law '") + spec +
                                    "': annulus:B needs 0 <= B < 1"),
              std::string::npos)
        << message_of(spec);
}

TEST(PressureLawReader, RejectsAnAnnulusWithoutANumber) {
  for (const char* spec : {"annulus:", "annulus:x", "annulus:nan", "annulus:inf"})
    EXPECT_NE(message_of(spec).find("annulus:B needs a finite number B"), std::string::npos)
        << spec << ": " << message_of(spec);
}

TEST(PressureLawReader, UnknownLawListsTheNamedLaws) {
  const std::string m = message_of("rings");
  EXPECT_NE(m.find("annulus:B (0 <= B < 1), ring or table:FILE"), std::string::npos) << m;
}

TEST(PressureLawReader, AnnulusLabelIsTheShortestTextOfB) {
  EXPECT_EQ(pressure_law_label(parse_pressure_law("annulus:0.3"), "annulus:0.3"), "annulus:0.3");
  EXPECT_EQ(pressure_law_label(parse_pressure_law("annulus:.50"), "annulus:.50"), "annulus:0.5");
  EXPECT_EQ(pressure_law_label(parse_pressure_law("ring"), "ring"), "ring");
  const double third = 1.0 / 3.0;
  char spec[64];
  std::snprintf(spec, sizeof spec, "annulus:%.17g", third);
  const std::string label = pressure_law_label(parse_pressure_law(spec), spec);
  EXPECT_EQ(parse_pressure_law(label).inner_radius(), third) << label;
}

// A temporary table file, removed at the end of the test.
struct TableFile {
  std::string path;
  // One file per test: ctest runs the tests of this file in parallel.
  explicit TableFile(const std::string& text)
      : path(::testing::TempDir() + "step_table_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".csv") {
    std::ofstream(path) << text;
  }
  ~TableFile() { std::remove(path.c_str()); }
};

TEST(PressureLawReader, ATableRowRepeatingRhoStatesAStep) {
  const TableFile file("rho,sigma0\n0,0\n0.3,0\n0.3,1\n1,1\n");
  const auto law = load_pressure_table(file.path);
  EXPECT_EQ(law.steps(), std::vector<double>{0.3});
  EXPECT_EQ(law(0.2, 0.8), 0.0);
  EXPECT_EQ(law(0.5, 0.5), 1.0);
}

TEST(PressureLawReader, AThirdRowWithTheSameRhoIsRejectedAtItsLine) {
  const TableFile file("rho,sigma0\n0,0\n0.3,0\n0.3,1\n0.3,2\n1,1\n");
  try {
    load_pressure_table(file.path);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 5u);
    EXPECT_EQ(e.column(), 1u);
    EXPECT_NE(std::string(e.what()).find("a step takes exactly two rows with the same rho"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace frictionid::pressure_law_reader_test

namespace frictionid::pressure_law_reader_test {
namespace {

// A table past the sample limit is refused at once, at the first sample too many: its exact
// model's set-up would take minutes and (before) ignored Ctrl-C while it ran.
TEST(PressureLawReader, ATableOfMoreSamplesThanTheLimitIsRefusedAtTheFirstOneTooMany) {
  std::string text = "rho,sigma0\n";
  const std::size_t n = kMaxPressureTableSamples + 5;
  for (std::size_t i = 0; i < n; ++i) {
    const double rho = static_cast<double>(i) / static_cast<double>(n - 1);
    text += std::to_string(rho) + "," + std::to_string(1.0 - rho * rho) + "\n";
  }
  const TableFile file(text);
  try {
    load_pressure_table(file.path);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), kMaxPressureTableSamples + 2);  // the header, then the samples
    EXPECT_NE(std::string(e.what()).find("more than 20000 samples"), std::string::npos) << e.what();
  }
  // At the limit the table is read.
  std::string at_limit = "rho,sigma0\n";
  for (std::size_t i = 0; i < kMaxPressureTableSamples; ++i) {
    const double rho = static_cast<double>(i) / static_cast<double>(kMaxPressureTableSamples - 1);
    at_limit += std::to_string(rho) + "," + std::to_string(1.0 - rho * rho) + "\n";
  }
  const TableFile limit(at_limit);
  EXPECT_NO_THROW(load_pressure_table(limit.path));
}

}  // namespace
}  // namespace frictionid::pressure_law_reader_test
