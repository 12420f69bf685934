#include <frictionid/io/dataset_csv.hpp>

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>

#include <frictionid/io/input_error.hpp>

namespace frictionid::dataset_csv_test {
namespace {

namespace fs = std::filesystem;

std::uint64_t bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

::testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << text << "' does not contain '" << part << "'";
}

// Each test gets its own fresh directory under the system temp directory, removed afterwards.
class DatasetCsv : public ::testing::Test {
 protected:
  void SetUp() override {
    std::random_device rd;
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("frictionid_io_test_" + std::string(info->name()) + "_" +
                                        std::to_string(rd()) + "_" + std::to_string(rd()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  // Writes `content` byte for byte and returns the path.
  std::string write(const std::string& content, const std::string& name = "data.csv") {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << content;
    return p.string();
  }

  // Loads `content` from a pipe (its /dev/fd path), written by another thread: the first bytes
  // one at a time, then the rest, in pieces as a pipe delivers them.
  static Dataset load_piped(const std::string& content) {
    std::signal(SIGPIPE, SIG_IGN);  // should the reader stop early, the writer gets EPIPE
    int fds[2];
    if (::pipe(fds) != 0) throw std::runtime_error("pipe failed");
    std::thread writer([&content, w = fds[1]] {
      for (std::size_t done = 0; done < content.size();) {
        const std::size_t piece = done < 8 ? 1 : std::min<std::size_t>(content.size() - done, 4096);
        const ssize_t n = ::write(w, content.data() + done, piece);
        if (n <= 0) break;
        done += static_cast<std::size_t>(n);
      }
      ::close(w);
    });
    const auto finish = [&] {
      ::close(fds[0]);
      writer.join();
    };
    try {
      Dataset d = load_dataset_csv("/dev/fd/" + std::to_string(fds[0]));
      finish();
      return d;
    } catch (...) {
      finish();
      throw;
    }
  }

  // The InputError that loading `path` throws, or a test failure when it loads.
  static InputError rejected(const std::string& path, const ColumnMap& map = {}) {
    try {
      load_dataset_csv(path, map);
    } catch (const InputError& e) {
      return e;
    }
    ADD_FAILURE() << "expected an InputError for " << path;
    return InputError("(no error thrown)");
  }

  // Loads a file whose third line has `text` in column 3 (omega) and expects a rejection there.
  void expect_bad_omega(const std::string& text, const std::string& reason) {
    SCOPED_TRACE("omega = '" + text + "'");
    const std::string p = write("v_x,v_y,omega,N,R,T_x\n1,0,2,3,4,5\n1,0," + text + ",3,4,5\n");
    const InputError e = rejected(p);
    EXPECT_EQ(e.file(), p);
    EXPECT_EQ(e.line(), 3u);
    EXPECT_EQ(e.column(), 3u);
    EXPECT_TRUE(Contains(e.what(), p + ":3:3: "));
    EXPECT_TRUE(Contains(e.what(), "'" + text + "'"));
    EXPECT_TRUE(Contains(e.what(), "omega"));
    EXPECT_TRUE(Contains(e.what(), reason));
  }

  fs::path dir_;
};

// ---- what is accepted ----

TEST_F(DatasetCsv, ReadsCanonicalColumnsInAnyOrder) {
  const std::string p = write("R,N,omega,v_y,v_x,M_z,T_x\n0.5,10,3,0.25,1.5,-0.125,2\n");
  const Dataset d = load_dataset_csv(p);
  ASSERT_EQ(d.rows(), 1u);
  EXPECT_EQ(d.source, p);
  EXPECT_EQ(d.v_x[0], 1.5);
  EXPECT_EQ(d.v_y[0], 0.25);
  EXPECT_EQ(d.omega[0], 3.0);
  EXPECT_EQ(d.N[0], 10.0);
  EXPECT_EQ(d.R[0], 0.5);
  EXPECT_EQ(d.value[int(Channel::T_x)][0], 2.0);
  EXPECT_EQ(d.value[int(Channel::M_z)][0], -0.125);
}

TEST_F(DatasetCsv, SeventeenDigitValuesRoundTripBitIdentical) {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-320, 300);
  const int rows = 3000;
  std::vector<std::array<double, 9>> truth(rows);
  std::string csv = "v_x,v_y,omega,N,R,T_x,T_y,M_z,M_roll\n";
  char buf[40];
  for (int i = 0; i < rows; ++i) {
    auto& t = truth[i];
    for (int k = 0; k < 9; ++k) {
      double x = unit(rng) * std::pow(10.0, exponent(rng));
      if (k == 0) x = unit(rng) * 1e-300;            // 1e-300 scale
      if (k == 1) x = std::ldexp(unit(rng), -1050);  // subnormal
      if (k == 2 && i % 5 == 0) x = std::numeric_limits<double>::denorm_min() * (i + 1);
      if (k == 3 || k == 4) x = std::fabs(x) + std::numeric_limits<double>::denorm_min();  // > 0
      if (k == 5 && i == 0) x = -0.0;
      t[k] = x;
      std::snprintf(buf, sizeof buf, "%.17g", x);
      csv += buf;
      csv += k < 8 ? ',' : '\n';
    }
  }
  const Dataset d = load_dataset_csv(write(csv));
  ASSERT_EQ(d.rows(), std::size_t(rows));
  for (int i = 0; i < rows; ++i) {
    const auto& t = truth[i];
    ASSERT_EQ(bits(d.v_x[i]), bits(t[0])) << i;
    ASSERT_EQ(bits(d.v_y[i]), bits(t[1])) << i;
    ASSERT_EQ(bits(d.omega[i]), bits(t[2])) << i;
    ASSERT_EQ(bits(d.N[i]), bits(t[3])) << i;
    ASSERT_EQ(bits(d.R[i]), bits(t[4])) << i;
    for (int c = 0; c < 4; ++c) ASSERT_EQ(bits(d.value[c][i]), bits(t[5 + c])) << i;  // T_x..M_roll
  }
}

TEST_F(DatasetCsv, LineHoldsOneBasedFileLineOfEachRow) {
  const Dataset d = load_dataset_csv(write("v_x,omega,N,R,T_x\n1,2,3,4,5\n\n6,7,8,9,10\n"));
  ASSERT_EQ(d.rows(), 2u);
  EXPECT_EQ(d.line, (std::vector<std::size_t>{2, 4}));
}

TEST_F(DatasetCsv, VyDefaultsToZeroWhenColumnAbsent) {
  const Dataset d = load_dataset_csv(write("v_x,omega,N,R,T_x\n1,2,3,4,5\n-1,2,3,4,5\n"));
  ASSERT_EQ(d.rows(), 2u);
  EXPECT_EQ(d.v_y, (std::vector<double>{0.0, 0.0}));
}

TEST_F(DatasetCsv, RowMayLeaveSomeChannelsEmptyAndPresentSaysWhich) {
  const Dataset d =
      load_dataset_csv(write("v_x,omega,N,R,T_x,M_z\n1,2,3,4,5,\n1,2,3,4,,6\n1,2,3,4,7,8\n"));
  ASSERT_EQ(d.rows(), 3u);
  const int tx = int(Channel::T_x), mz = int(Channel::M_z);
  EXPECT_EQ(d.present[tx], (std::vector<std::uint8_t>{1, 0, 1}));
  EXPECT_EQ(d.present[mz], (std::vector<std::uint8_t>{0, 1, 1}));
  EXPECT_EQ(d.value[tx][0], 5.0);
  EXPECT_TRUE(std::isnan(d.value[tx][1]));
  EXPECT_TRUE(std::isnan(d.value[mz][0]));
  EXPECT_EQ(d.value[mz][2], 8.0);
  EXPECT_TRUE(d.has_channel(Channel::T_x));
  EXPECT_TRUE(d.has_channel(Channel::M_z));
}

TEST_F(DatasetCsv, ChannelWithoutColumnHasRowsButNonePresent) {
  const Dataset d = load_dataset_csv(write("v_x,omega,N,R,T_x\n1,2,3,4,5\n"));
  for (Channel c : {Channel::T_y, Channel::M_z, Channel::M_roll}) {
    EXPECT_EQ(d.present[int(c)], (std::vector<std::uint8_t>{0}));
    EXPECT_EQ(d.value[int(c)].size(), 1u);
    EXPECT_FALSE(d.has_channel(c));
    EXPECT_FALSE(d.has_sigma(c));
  }
}

TEST_F(DatasetCsv, SigmaColumnsAreReadPerChannel) {
  const Dataset d = load_dataset_csv(
      write("v_x,omega,N,R,T_x,sigma_T_x,M_z\n1,2,3,4,5,0.1,6\n1,2,3,4,5,0.2,6\n"));
  EXPECT_TRUE(d.has_sigma(Channel::T_x));
  EXPECT_FALSE(d.has_sigma(Channel::M_z));
  EXPECT_EQ(d.sigma[int(Channel::T_x)], (std::vector<double>{0.1, 0.2}));
  EXPECT_TRUE(d.sigma[int(Channel::M_z)].empty());
}

TEST_F(DatasetCsv, SigmaIsIgnoredWhereItsChannelIsAbsent) {
  const Dataset d =
      load_dataset_csv(write("v_x,omega,N,R,T_x,sigma_T_x,M_z\n1,2,3,4,,,6\n1,2,3,4,,-1,6\n"));
  ASSERT_EQ(d.rows(), 2u);
  EXPECT_TRUE(std::isnan(d.sigma[int(Channel::T_x)][0]));
  EXPECT_TRUE(std::isnan(d.sigma[int(Channel::T_x)][1]));
}

TEST_F(DatasetCsv, CrlfLineEndsAccepted) {
  const Dataset d = load_dataset_csv(write("v_x,omega,N,R,T_x\r\n1,2,3,4,5\r\n6,7,8,9,10\r\n"));
  ASSERT_EQ(d.rows(), 2u);
  EXPECT_EQ(d.value[int(Channel::T_x)][0], 5.0);
  EXPECT_EQ(d.value[int(Channel::T_x)][1], 10.0);
}

TEST_F(DatasetCsv, Utf8BomAcceptedAndStripped) {
  const Dataset d = load_dataset_csv(write("\xEF\xBB\xBFv_x,omega,N,R,T_x\n1,2,3,4,5\n"));
  ASSERT_EQ(d.rows(), 1u);
  EXPECT_EQ(d.v_x[0], 1.0);
  EXPECT_EQ(d.line[0], 2u);
}

TEST_F(DatasetCsv, BlankTrailingLinesAccepted) {
  const Dataset d = load_dataset_csv(write("v_x,omega,N,R,T_x\n1,2,3,4,5\n\n  \n\r\n"));
  EXPECT_EQ(d.rows(), 1u);
}

TEST_F(DatasetCsv, LastLineWithoutNewlineAccepted) {
  const Dataset d = load_dataset_csv(write("v_x,omega,N,R,T_x\n1,2,3,4,5"));
  ASSERT_EQ(d.rows(), 1u);
  EXPECT_EQ(d.value[0][0], 5.0);
}

// A pipe can be read once only: the encoding check looks at the reader's first bytes instead of
// opening the input again, so the header is still there for the reader.
TEST_F(DatasetCsv, PipeReadWithItsHeader) {
  std::string rows;
  for (int i = 1; i <= 5000; ++i) rows += std::to_string(i) + ",2,2000,0.05,7\n";
  const Dataset d = load_piped("\xEF\xBB\xBFv_x,omega,N,R,T_x\n" + rows);
  ASSERT_EQ(d.rows(), 5000u);
  EXPECT_EQ(d.v_x.front(), 1.0);
  EXPECT_EQ(d.v_x.back(), 5000.0);
  EXPECT_EQ(d.line.back(), 5001u);
}

TEST_F(DatasetCsv, CompressedDataThroughAPipeIsNamed) {
  try {
    load_piped(std::string("\x1F\x8B\x08\x00\x00\x00\x00\x00\x00\x03", 10) + std::string(200, 'x'));
    ADD_FAILURE() << "gzip data was read";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.what(), "gzip")) << e.what();
  }
}

TEST_F(DatasetCsv, UnknownExtraColumnsIgnored) {
  const Dataset d =
      load_dataset_csv(write("run,v_x,omega,N,note,R,T_x,\nA,1,2,3,hello world,4,5,\n"));
  ASSERT_EQ(d.rows(), 1u);
  EXPECT_EQ(d.R[0], 4.0);
}

TEST_F(DatasetCsv, QuotedFieldsAndSpacesAroundFieldsAccepted) {
  const Dataset d = load_dataset_csv(
      write("\"v_x\", omega ,N,R,T_x,comment\n\"1.5\" , 2 ,3,4,5,\"a, \"\"quoted\"\" note\"\n"));
  ASSERT_EQ(d.rows(), 1u);
  EXPECT_EQ(d.v_x[0], 1.5);
  EXPECT_EQ(d.omega[0], 2.0);
}

TEST_F(DatasetCsv, LeadingPlusAndExponentFormsAccepted) {
  const Dataset d = load_dataset_csv(write("v_x,omega,N,R,T_x\n+1.0E+00,-2e-3,.5,5.,1e-300\n"));
  EXPECT_EQ(d.v_x[0], 1.0);
  EXPECT_EQ(d.omega[0], -2e-3);
  EXPECT_EQ(d.N[0], 0.5);
  EXPECT_EQ(d.R[0], 5.0);
  EXPECT_EQ(d.value[0][0], 1e-300);
}

// ---- column map ----

TEST_F(DatasetCsv, ColumnMapRenamesHeaderColumns) {
  const std::string p = write("speed,spin,load,radius,Fx,Mz\n1,2,3,4,5,6\n");
  const Dataset d = load_dataset_csv(p, ColumnMap{{{"v_x", "speed"},
                                                   {"omega", "spin"},
                                                   {"N", "load"},
                                                   {"R", "radius"},
                                                   {"T_x", "Fx"},
                                                   {"M_z", "Mz"}}});
  ASSERT_EQ(d.rows(), 1u);
  EXPECT_EQ(d.v_x[0], 1.0);
  EXPECT_EQ(d.omega[0], 2.0);
  EXPECT_EQ(d.N[0], 3.0);
  EXPECT_EQ(d.R[0], 4.0);
  EXPECT_EQ(d.value[int(Channel::T_x)][0], 5.0);
  EXPECT_EQ(d.value[int(Channel::M_z)][0], 6.0);
}

TEST_F(DatasetCsv, RemappedCanonicalNameIsReadOnlyFromItsNewHeader) {
  const Dataset d = load_dataset_csv(write("v_x,omega,spin,N,R,T_x\n1,99,2,3,4,5\n"),
                                     ColumnMap{{{"omega", "spin"}}});
  EXPECT_EQ(d.omega[0], 2.0);
}

TEST_F(DatasetCsv, ColumnMapCanSwapTwoCanonicalColumns) {
  const Dataset d = load_dataset_csv(write("v_x,v_y,omega,N,R,T_x\n1,2,3,4,5,6\n"),
                                     ColumnMap{{{"v_x", "v_y"}, {"v_y", "v_x"}}});
  EXPECT_EQ(d.v_x[0], 2.0);
  EXPECT_EQ(d.v_y[0], 1.0);
}

TEST_F(DatasetCsv, ColumnMapGivingOneHeaderToTwoColumnsRejected) {
  const InputError e =
      rejected(write("v_x,v_y,omega,N,R,T_x\n1,2,3,4,5,6\n"), ColumnMap{{{"v_x", "v_y"}}});
  EXPECT_TRUE(Contains(e.what(), "'v_y' would supply both v_x and v_y"));
}

TEST_F(DatasetCsv, MissingRemappedColumnNamesBothNames) {
  const std::string p = write("v_x,omega,N,R,T_x\n1,2,3,4,5\n");
  const InputError e = rejected(p, ColumnMap{{{"omega", "spin"}}});
  EXPECT_TRUE(Contains(e.what(), p + ":1: "));
  EXPECT_TRUE(Contains(e.what(), "'spin' (omega)"));
}

// ---- file-level rejections ----

TEST_F(DatasetCsv, MissingFileRejected) {
  const std::string p = (dir_ / "nope.csv").string();
  const InputError e = rejected(p);
  EXPECT_TRUE(Contains(e.what(), p + ": cannot open file"));
}

TEST_F(DatasetCsv, DirectoryRejected) {
  EXPECT_TRUE(Contains(rejected(dir_.string()).what(), "directory"));
}

TEST_F(DatasetCsv, EmptyFileRejected) {
  const std::string p = write("");
  EXPECT_TRUE(Contains(rejected(p).what(), p + ": empty file"));
  EXPECT_TRUE(Contains(rejected(write("\xEF\xBB\xBF", "bom_only.csv")).what(), "empty file"));
}

TEST_F(DatasetCsv, EmptyHeaderLineRejected) {
  const std::string p = write("\nv_x,omega,N,R,T_x\n1,2,3,4,5\n");
  EXPECT_TRUE(Contains(rejected(p).what(), p + ":1: header row is empty"));
}

TEST_F(DatasetCsv, HeaderOnlyRejected) {
  const std::string p = write("v_x,omega,N,R,T_x\n\n\n");
  const InputError e = rejected(p);
  EXPECT_TRUE(Contains(e.what(), p + ":1: "));
  EXPECT_TRUE(Contains(e.what(), "not followed by any data row"));
}

// ---- header rejections ----

TEST_F(DatasetCsv, MissingRequiredColumnNamedAndHeaderListed) {
  const std::string p = write("v_x,N,T_x\n1,3,5\n");
  const InputError e = rejected(p);
  EXPECT_EQ(e.line(), 1u);
  EXPECT_TRUE(Contains(e.what(), p + ":1: missing required column(s) 'omega', 'R'"));
  EXPECT_TRUE(Contains(e.what(), "the header has 'v_x', 'N', 'T_x'"));
}

TEST_F(DatasetCsv, MisspelledRequiredColumnGetsDidYouMean) {
  const std::string p = write("v_x,omgea,N,R,T_x\n1,2,3,4,5\n");
  const InputError e = rejected(p);
  EXPECT_EQ(e.column(), 2u);
  EXPECT_TRUE(Contains(e.what(), p + ":1:2: "));
  EXPECT_TRUE(Contains(e.what(), "did you mean 'omega'? (column 2 is 'omgea')"));
}

TEST_F(DatasetCsv, WrongCaseOfRequiredColumnGetsDidYouMean) {
  const InputError e = rejected(write("v_x,omega,n,R,T_x\n1,2,3,4,5\n"));
  EXPECT_EQ(e.column(), 3u);
  EXPECT_TRUE(Contains(e.what(), "did you mean 'N'? (column 3 is 'n')"));
}

TEST_F(DatasetCsv, MissingColumnWithoutLookalikeSuggestsColumnMap) {
  const InputError e = rejected(write("speed,omega,N,R,T_x\n1,2,3,4,5\n"));
  EXPECT_EQ(e.column(), 0u);
  EXPECT_TRUE(Contains(e.what(), "missing required column(s) 'v_x'"));
  EXPECT_TRUE(Contains(e.what(), "column map canonical=header"));
}

TEST_F(DatasetCsv, SuggestionPicksTheClosestChannelName) {
  const InputError e = rejected(write("v_x,omega,N,R,M_Z\n1,2,3,4,5\n"));
  EXPECT_TRUE(Contains(e.what(), "did you mean 'M_z'? (column 5 is 'M_Z')"));
}

TEST_F(DatasetCsv, MisspeltColumnMapTargetIsPointedOut) {
  const InputError e =
      rejected(write("speed,omega,N,R,T_x\n1,2,3,4,5\n"), ColumnMap{{{"v_x", "sped"}}});
  EXPECT_EQ(e.column(), 1u);
  EXPECT_TRUE(Contains(e.what(), "missing required column(s) 'sped' (v_x)"));
  EXPECT_TRUE(Contains(e.what(), "column 1 'speed' is close to 'sped' given by the column map"));
}

TEST_F(DatasetCsv, NoChannelColumnRejected) {
  const std::string p = write("v_x,omega,N,R,T_X\n1,2,3,4,5\n");
  const InputError e = rejected(p);
  EXPECT_TRUE(Contains(e.what(), p + ":1:5: no measured channel column"));
  EXPECT_TRUE(Contains(e.what(), "'T_x', 'T_y', 'M_z', 'M_roll'"));
  EXPECT_TRUE(Contains(e.what(), "did you mean 'T_x'? (column 5 is 'T_X')"));
}

TEST_F(DatasetCsv, SigmaColumnWithoutItsChannelRejected) {
  const std::string p = write("v_x,omega,N,R,T_x,sigma_M_z\n1,2,3,4,5,0.1\n");
  const InputError e = rejected(p);
  EXPECT_TRUE(Contains(e.what(), p + ":1:6: column 'sigma_M_z' is given but there is no column "
                                     "'M_z'"));
}

TEST_F(DatasetCsv, DuplicateColumnRejected) {
  const std::string p = write("v_x,omega,N,R,T_x,omega\n1,2,3,4,5,2\n");
  const InputError e = rejected(p);
  EXPECT_EQ(e.column(), 6u);
  EXPECT_TRUE(Contains(e.what(), p + ":1:6: duplicate column 'omega' (also column 2)"));
}

TEST_F(DatasetCsv, SemicolonDelimitedFileRejectedWithDelimiterHint) {
  const std::string p = write("v_x;omega;N;R;T_x\n1;2;3;4;5\n");
  const InputError e = rejected(p);
  EXPECT_TRUE(Contains(e.what(), p + ":1:1: header is a single field 'v_x;omega;N;R;T_x'"));
  EXPECT_TRUE(Contains(e.what(), "';' characters"));
  EXPECT_TRUE(Contains(e.what(), "expected ','"));
}

TEST_F(DatasetCsv, TabDelimitedFileRejectedWithDelimiterHint) {
  const std::string p = write("v_x\tomega\tN\tR\tT_x\n1\t2\t3\t4\t5\n");
  const InputError e = rejected(p);
  EXPECT_TRUE(Contains(e.what(), p + ":1:1: header is a single field"));
  EXPECT_TRUE(Contains(e.what(), "tab characters"));
}

TEST_F(DatasetCsv, UnterminatedQuoteRejected) {
  const std::string p = write("v_x,omega,N,R,T_x\n1,2,\"3,4,5\n");
  const InputError e = rejected(p);
  EXPECT_TRUE(Contains(e.what(), p + ":2:3: unterminated quoted field '\"3,4,5'"));
}

// ---- row rejections ----

TEST_F(DatasetCsv, RowWithTooFewFieldsRejected) {
  const std::string p = write("v_x,omega,N,R,T_x\n1,2,3,4,5\n1,2,3\n");
  const InputError e = rejected(p);
  EXPECT_TRUE(Contains(e.what(), p + ":3:4: row has 3 fields, expected 5"));
}

TEST_F(DatasetCsv, RowWithTooManyFieldsRejected) {
  const std::string p = write("v_x,omega,N,R,T_x\n1,2,3,4,5,6.5\n");
  const InputError e = rejected(p);
  EXPECT_TRUE(Contains(e.what(), p + ":2:6: row has 6 fields, expected 5"));
  EXPECT_TRUE(Contains(e.what(), "'6.5'"));
}

TEST_F(DatasetCsv, RowWithOtherDelimiterGetsHint) {
  const std::string p = write("v_x,omega,N,R,T_x\n1;2;3;4;5\n");
  EXPECT_TRUE(Contains(rejected(p).what(), "';' characters"));
}

TEST_F(DatasetCsv, NonNumericValueRejected) {
  expect_bad_omega("abc", "not a number");
}
TEST_F(DatasetCsv, TrailingGarbageRejected) {
  expect_bad_omega("2.5rad", "unexpected characters");
  expect_bad_omega("2.5 3", "unexpected characters");
  expect_bad_omega("1e", "unexpected characters");
}
TEST_F(DatasetCsv, NaNTextRejected) {
  expect_bad_omega("nan", "NaN is not allowed");
  expect_bad_omega("NaN", "NaN is not allowed");
}
TEST_F(DatasetCsv, InfTextRejected) {
  expect_bad_omega("inf", "Inf is not allowed");
  expect_bad_omega("-Infinity", "Inf is not allowed");
}
TEST_F(DatasetCsv, HexFloatRejected) {
  expect_bad_omega("0x1p3", "hexadecimal");
}
TEST_F(DatasetCsv, OverflowRejected) {
  expect_bad_omega("1e400", "out of the double range");
}
TEST_F(DatasetCsv, UnderflowToZeroRejected) {
  expect_bad_omega("1e-400", "out of the double range");
}

TEST_F(DatasetCsv, EmptyRequiredFieldRejected) {
  const std::string p = write("v_x,omega,N,R,T_x\n1,,3,4,5\n");
  const InputError e = rejected(p);
  EXPECT_TRUE(Contains(e.what(), p + ":2:2: empty field in column 'omega'"));
}

TEST_F(DatasetCsv, EmptyVyFieldRejectedWhenColumnPresent) {
  const std::string p = write("v_x,v_y,omega,N,R,T_x\n1, ,2,3,4,5\n");
  EXPECT_TRUE(Contains(rejected(p).what(), p + ":2:2: empty field in column 'v_y'"));
}

TEST_F(DatasetCsv, NonPositiveNRejected) {
  for (const char* n : {"0", "-0", "-3"}) {
    const std::string p = write(std::string("v_x,omega,N,R,T_x\n1,2,") + n + ",4,5\n");
    const InputError e = rejected(p);
    EXPECT_TRUE(Contains(e.what(), p + ":2:3: column 'N' has '" + n + "'"));
    EXPECT_TRUE(Contains(e.what(), "> 0"));
  }
}

TEST_F(DatasetCsv, NonPositiveRRejected) {
  const std::string p = write("radius,v_x,omega,N,T_x\n0.5,1,2,3,4\n-0.5,1,2,3,4\n");
  const InputError e = rejected(p, ColumnMap{{{"R", "radius"}}});
  EXPECT_TRUE(Contains(e.what(), p + ":3:1: column 'radius' (R) has '-0.5'"));
}

TEST_F(DatasetCsv, RowWithoutAnyChannelRejected) {
  const std::string p = write("v_x,omega,N,T_x,R,M_z\n1,2,3,4,5,6\n1,2,3,,5,\n");
  const InputError e = rejected(p);
  EXPECT_TRUE(Contains(e.what(), p + ":3:4: no measured channel in this row"));
}

TEST_F(DatasetCsv, EmptySigmaWhereChannelPresentRejected) {
  const std::string p = write("v_x,omega,N,R,T_x,sigma_T_x\n1,2,3,4,5,\n");
  EXPECT_TRUE(Contains(rejected(p).what(), p + ":2:6: empty field in column 'sigma_T_x'"));
}

TEST_F(DatasetCsv, NonPositiveSigmaRejected) {
  const std::string p = write("v_x,omega,N,R,T_x,sigma_T_x\n1,2,3,4,5,0\n");
  const InputError e = rejected(p);
  EXPECT_TRUE(Contains(e.what(), p + ":2:6: column 'sigma_T_x' has '0'"));
  EXPECT_TRUE(Contains(e.what(), "> 0"));
}

TEST_F(DatasetCsv, NonFiniteSigmaRejected) {
  const std::string p = write("v_x,omega,N,R,T_x,sigma_T_x\n1,2,3,4,5,inf\n");
  EXPECT_TRUE(Contains(rejected(p).what(), p + ":2:6: column 'sigma_T_x' has 'inf'"));
}

TEST_F(DatasetCsv, BadNumberInChannelColumnRejected) {
  const std::string q = write("v_x,omega,N,R,T_x,M_z\n1,2,3,4,5,6\n1,2,3,4,5,six\n");
  EXPECT_TRUE(Contains(rejected(q).what(), q + ":3:6: column 'M_z' has 'six'"));
}

// ---- a large file, read in parts side by side ----

// About 8 MB of rows of every kind the reader meets: CRLF and LF line ends, blank lines,
// quoted and padded fields, empty channel fields, sigma columns, a text column. Row i's omega is
// i, so a row's place shows in its values.
std::string varied_rows(std::size_t rows) {
  std::string out = "v_x,omega,N,R,T_x,sigma_T_x,M_z,label\n";
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  char buf[256];
  for (std::size_t i = 1; i <= rows; ++i) {
    const int kind = static_cast<int>(i % 7);
    const double x = u(rng);
    if (kind == 3)
      std::snprintf(buf, sizeof buf, "%.17g, %zu ,2000,0.05,,,%.6g,\"run \"\"%zu\"\"\"\r\n", x, i,
                    x * 2, i % 5);
    else
      std::snprintf(buf, sizeof buf, "%.17g,%zu,%d,0.05,%.17g,%.3g,%s,run%zu\n", x, i, 1000 + kind,
                    x * 0.7, 0.01 + (i % 3) * 0.001, kind == 5 ? "" : "1.25", i % 5);
    out += buf;
    if (i % 1001 == 0) out += i % 2 ? "\n" : "\r\n";  // blank lines
  }
  return out;
}

void expect_same(const Dataset& a, const Dataset& b) {
  ASSERT_EQ(a.rows(), b.rows());
  EXPECT_EQ(a.line, b.line);
  for (auto [x, y] : {std::pair{&a.v_x, &b.v_x}, std::pair{&a.v_y, &b.v_y},
                      std::pair{&a.omega, &b.omega}, std::pair{&a.N, &b.N}, std::pair{&a.R, &b.R}})
    EXPECT_TRUE(*x == *y);
  for (int c = 0; c < kChannelCount; ++c) {
    EXPECT_EQ(a.present[c], b.present[c]);
    // NaN where a channel is not measured: compared as bits.
    const auto same_bits = [](const std::vector<double>& x, const std::vector<double>& y) {
      return x.size() == y.size() &&
             std::equal(x.begin(), x.end(), y.begin(),
                        [](double p, double q) { return bits(p) == bits(q); });
    };
    EXPECT_TRUE(same_bits(a.value[c], b.value[c])) << c;
    EXPECT_TRUE(same_bits(a.sigma[c], b.sigma[c])) << c;
  }
  EXPECT_EQ(a.extra_names, b.extra_names);
  EXPECT_EQ(a.extra_values, b.extra_values);
}

TEST_F(DatasetCsv, ALargeFileReadsAsThroughAPipeRowForRow) {
  const std::string content = varied_rows(130000);
  ASSERT_GT(content.size(), 8u << 20);
  const Dataset from_file = load_dataset_csv(write(content));
  const Dataset from_pipe = load_piped(content);  // a pipe is read in one piece
  expect_same(from_file, from_pipe);
  EXPECT_EQ(from_file.omega.back(), 130000.0);
  EXPECT_EQ(from_file.extra_values[0][2], "run \"3\"");
}

TEST_F(DatasetCsv, ALargeFileReportsItsFirstBadRowWithItsLineWhereverItIs) {
  const std::string good = varied_rows(130000);
  // The lines of rows 30,000, 70,000 and 110,000: in the first, a middle and the last part.
  auto line_start = [&](std::size_t omega) {
    const std::string key = "," + std::to_string(omega) + ",";
    return good.find(key);
  };
  for (std::size_t bad_row : {110000u, 70000u, 30000u}) {
    std::string content = good;
    const std::size_t at = line_start(bad_row);
    ASSERT_NE(at, std::string::npos);
    content.replace(at + 1, std::to_string(bad_row).size(), "x" + std::to_string(bad_row));
    // A second bad row later on never wins over the first.
    const std::size_t later = line_start(119000);
    content.replace(later + 1, 6, "y19000");
    const std::string p = write(content, "bad" + std::to_string(bad_row) + ".csv");
    const InputError e = rejected(p);
    std::string piped;
    try {
      load_piped(content);
    } catch (const InputError& pe) {
      piped = pe.message();
      EXPECT_EQ(e.line(), pe.line());
    }
    const std::size_t line = static_cast<std::size_t>(
        std::count(content.begin(), content.begin() + static_cast<long>(at), '\n') + 1);
    EXPECT_EQ(e.line(), line) << bad_row;
    EXPECT_EQ(e.column(), 2u);
    EXPECT_EQ(e.message(), piped);
    EXPECT_TRUE(Contains(e.what(), p + ":" + std::to_string(line) + ":2: column 'omega' has 'x" +
                                       std::to_string(bad_row) + "'"));
  }
}

}  // namespace
}  // namespace frictionid::dataset_csv_test
