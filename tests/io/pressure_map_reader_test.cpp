// The pressure-map file of --contact map:FILE: a rectangular grid of x,y,sigma0 samples in any row
// order, read into the model's PressureMap, and every way a file can fail to be one, each named
// at its file, line and column.
#include <frictionid/io/pressure_map_reader.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include <frictionid/io/input_error.hpp>

namespace frictionid::pressure_map_reader_test {
namespace {

// A temporary map file, removed at the end of the test (one per test: ctest runs them apart).
struct MapFile {
  std::string path;
  explicit MapFile(const std::string& text)
      : path(::testing::TempDir() + "pressure_map_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".csv") {
    std::ofstream(path, std::ios::binary) << text;
  }
  ~MapFile() { std::remove(path.c_str()); }
};

// The error a file gives, or a failure when it is accepted.
InputError error_of(const std::string& text) {
  const MapFile file(text);
  try {
    load_pressure_map(file.path);
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), file.path);
    return e;
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return InputError("(accepted)");
}

bool says(const InputError& e, const std::string& words) {
  return std::string(e.what()).find(words) != std::string::npos;
}

TEST(PressureMapReader, AGridInAnyRowOrderReadsToTheSamplesAtTheirPoints) {
  // 3 x 2 grid, uneven spacing, rows shuffled, columns in another order than x,y,sigma0.
  const MapFile file(
      "\xEF\xBB\xBFsigma0,y,x\r\n"
      "# a comment\n"
      "5,0.5,0.25\n"
      "1,-0.5,-1\n"
      "\n"
      "2,-0.5,0.25\n"
      "4,0.5,-1\n"
      "3,-0.5,1\n"
      "6,0.5,1\n");
  const auto map = load_pressure_map(file.path);
  EXPECT_EQ(map->x, (std::vector<double>{-1, 0.25, 1}));
  EXPECT_EQ(map->y, (std::vector<double>{-0.5, 0.5}));
  EXPECT_EQ(map->sample(0, 0), 1);
  EXPECT_EQ(map->sample(1, 0), 2);
  EXPECT_EQ(map->sample(2, 0), 3);
  EXPECT_EQ(map->sample(0, 1), 4);
  EXPECT_EQ(map->sample(1, 1), 5);
  EXPECT_EQ(map->sample(2, 1), 6);
  EXPECT_EQ(map->source, file.path);
}

TEST(PressureMapReader, AMapWrittenWithSeventeenDigitsReadsBackBitIdentical) {
  // The round trip: every sample written with %.17g comes back as the same double.
  model::PressureMap in;
  in.x = {-1.0, -1.0 / 3.0, 0.1, 1.0};
  in.y = {-0.7, 0.0, 2.0 / 3.0};
  for (std::size_t j = 0; j < in.ny(); ++j)
    for (std::size_t i = 0; i < in.nx(); ++i)
      in.sigma0.push_back((1.0 - in.x[i] * in.x[i] / 2.0) * (1.0 + in.y[j] / 7.0));
  std::string text = "x,y,sigma0\n";
  char buf[128];
  for (std::size_t j = in.ny(); j-- > 0;)  // written in another order than read
    for (std::size_t i = 0; i < in.nx(); ++i) {
      std::snprintf(buf, sizeof buf, "%.17g,%.17g,%.17g\n", in.x[i], in.y[j], in.sample(i, j));
      text += buf;
    }
  const MapFile file(text);
  const auto out = load_pressure_map(file.path);
  EXPECT_EQ(out->x, in.x);
  EXPECT_EQ(out->y, in.y);
  EXPECT_EQ(out->sigma0, in.sigma0);
}

TEST(PressureMapReader, AMissingGridPointIsNamedAtALineOfItsRow) {
  const InputError e = error_of("x,y,sigma0\n0,0,1\n1,0,1\n0,1,1\n");
  EXPECT_EQ(e.line(), 4u);  // the row y = 1 lacks x = 1
  EXPECT_EQ(e.column(), 1u);
  EXPECT_TRUE(says(e, "the grid has no point (x, y) = (1, 1)")) << e.what();
}

TEST(PressureMapReader, ADuplicatePointIsNamedAtItsSecondLine) {
  const InputError e = error_of("x,y,sigma0\n0,0,1\n1,0,1\n0,1,1\n1,1,1\n0,0,2\n");
  EXPECT_EQ(e.line(), 6u);
  EXPECT_EQ(e.column(), 1u);
  EXPECT_TRUE(says(e, "duplicate point (x, y) = (0, 0), first given on line 2")) << e.what();
}

TEST(PressureMapReader, ANegativeSampleIsNamedAtItsField) {
  const InputError e = error_of("x,y,sigma0\n0,0,1\n1,0,-0.5\n0,1,1\n1,1,1\n");
  EXPECT_EQ(e.line(), 3u);
  EXPECT_EQ(e.column(), 3u);
  EXPECT_TRUE(says(e, "sigma0 is -0.5 at (x, y) = (1, 0)")) << e.what();
}

TEST(PressureMapReader, ANonFiniteValueIsNamedAtItsField) {
  for (const char* bad : {"nan", "inf", "1e999", "0x1p3", ""}) {
    const InputError e =
        error_of(std::string("x,y,sigma0\n0,0,1\n1,") + bad + ",1\n0,1,1\n1,1,1\n");
    EXPECT_EQ(e.line(), 3u) << bad;
    EXPECT_EQ(e.column(), 2u) << bad;
    EXPECT_TRUE(says(e, "y: expected a finite number")) << e.what();
  }
}

TEST(PressureMapReader, MoreThanTenThousandSamplesIsRefusedAtTheFirstOneTooMany) {
  std::string text = "x,y,sigma0\n";
  for (int j = 0; j < 101; ++j)
    for (int i = 0; i < 100; ++i) text += std::to_string(i) + "," + std::to_string(j) + ",1\n";
  const InputError e = error_of(text);
  EXPECT_EQ(e.line(), 10002u);  // the header, then 10,000 samples
  EXPECT_TRUE(says(e, "more than 10000 samples")) << e.what();
  EXPECT_TRUE(says(e, "resample the map")) << e.what();
}

TEST(PressureMapReader, FewerThanTwoByTwoSamplesIsRefused) {
  const InputError one_y = error_of("x,y,sigma0\n0,0,1\n1,0,1\n2,0,1\n");
  EXPECT_EQ(one_y.line(), 4u);
  EXPECT_EQ(one_y.column(), 2u);
  EXPECT_TRUE(says(one_y, "only one distinct y value (0)")) << one_y.what();
  EXPECT_TRUE(says(one_y, "at least 2 x 2 samples (found 3 x 1)")) << one_y.what();
  const InputError one_x = error_of("x,y,sigma0\n0,0,1\n0,1,1\n");
  EXPECT_TRUE(says(one_x, "only one distinct x value (0)")) << one_x.what();
  const InputError none = error_of("x,y,sigma0\n");
  EXPECT_EQ(none.line(), 1u);
  EXPECT_TRUE(says(none, "not followed by any sample")) << none.what();
}

TEST(PressureMapReader, AMapWithoutLoadIsRefused) {
  const InputError e = error_of("x,y,sigma0\n0,0,0\n1,0,0\n0,1,0\n1,1,0\n");
  EXPECT_EQ(e.line(), 1u);
  EXPECT_EQ(e.column(), 3u);
  EXPECT_TRUE(says(e, "sigma0 is 0 at every sample: the map carries no load")) << e.what();
}

TEST(PressureMapReader, AHeaderWithoutTheThreeNamesIsRefused) {
  for (const char* header : {"a,b,c", "x,y", "x,y,sigma0,extra", "0,0,1"}) {
    const InputError e = error_of(std::string(header) + "\n0,0,1\n1,0,1\n0,1,1\n1,1,1\n");
    EXPECT_EQ(e.line(), 1u) << header;
    EXPECT_TRUE(says(e, "expected the header 'x,y,sigma0'")) << e.what();
  }
}

TEST(PressureMapReader, ARowWithAnotherNumberOfFieldsIsRefusedAtItsLine) {
  const InputError e = error_of("x,y,sigma0\n0,0,1\n1,0\n");
  EXPECT_EQ(e.line(), 3u);
  EXPECT_TRUE(says(e, "expected 3 comma-separated fields")) << e.what();
}

TEST(PressureMapReader, ContactLabelsSpellTheSpotAsTheCommandLineDoes) {
  EXPECT_EQ(contact_spot_label(model::ContactSpot::circle()), "circle");
  EXPECT_EQ(contact_spot_label(model::ContactSpot::ellipse(0.6)), "ellipse:0.6");
  EXPECT_EQ(contact_spot_label(model::ContactSpot::rect(1.0 / 3.0)), "rect:0.3333333333333333");
  auto map = std::make_shared<model::PressureMap>();
  map->source = "data/footprint_map.csv";
  EXPECT_EQ(contact_spot_label(model::ContactSpot::pressure_map(map)),
            "map:data/footprint_map.csv");
}

}  // namespace
}  // namespace frictionid::pressure_map_reader_test
