#include "io/line_reader.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <csignal>
#include <cstring>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <frictionid/io/input_error.hpp>
#include "support/scratch_dir.hpp"

namespace frictionid::io_detail::line_reader_test {
namespace {

using test::ScratchDir;

// Writes `content` byte for byte into a file of `dir` and returns its path.
std::string write(const ScratchDir& dir, const std::string& content) {
  const std::string path = dir / "lines.txt";
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

// Every line of the reader (with its length, which may include NUL bytes) until the end.
std::vector<std::string> all_lines(LineReader& reader) {
  std::vector<std::string> lines;
  while (const char* line = reader.next_line()) {
    EXPECT_EQ(line[reader.line_length()], '\0');
    lines.emplace_back(line, reader.line_length());
    EXPECT_EQ(reader.line_number(), lines.size());
  }
  return lines;
}

std::vector<std::string> all_lines(const std::string& path) {
  LineReader reader(path);
  return all_lines(reader);
}

// The InputError reading all of `path` throws, or a test failure when there is none.
InputError read_error(const std::string& path) {
  try {
    all_lines(path);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected an InputError for " << path;
  return InputError("(no error thrown)");
}

using Lines = std::vector<std::string>;

TEST(LineReader, LfEndsLinesAndIsNotPartOfThem) {
  ScratchDir dir("line_reader_lf");
  EXPECT_EQ(all_lines(write(dir, "a,b\nc\n")), (Lines{"a,b", "c"}));
}

TEST(LineReader, CrlfLosesItsCrButOtherCrsStay) {
  ScratchDir dir("line_reader_crlf");
  EXPECT_EQ(all_lines(write(dir, "a\r\nb\rc\r\n\r\nd\r\r\n")), (Lines{"a", "b\rc", "", "d\r"}));
}

TEST(LineReader, LastLineWithoutNewlineIsStillALine) {
  ScratchDir dir("line_reader_last");
  EXPECT_EQ(all_lines(write(dir, "a\nb")), (Lines{"a", "b"}));
  EXPECT_EQ(all_lines(write(dir, "a\nb\r")), (Lines{"a", "b"}));
}

TEST(LineReader, Utf8BomIsSkippedAtTheStartOnly) {
  ScratchDir dir("line_reader_bom");
  EXPECT_EQ(all_lines(write(dir, "\xEF\xBB\xBFv_x\n\xEF\xBB\xBFw\n")),
            (Lines{"v_x", "\xEF\xBB\xBFw"}));
  EXPECT_EQ(all_lines(write(dir, "\xEF\xBB\xBF")), Lines{});
  EXPECT_EQ(all_lines(write(dir, "\xEF\xBB")), (Lines{"\xEF\xBB"}));
}

TEST(LineReader, HeadHoldsTheFirstBytesAsTheyAre) {
  ScratchDir dir("line_reader_head");
  EXPECT_EQ(LineReader(write(dir, "\xEF\xBB\xBFv_x\r\n")).head(), "\xEF\xBB\xBFv_x\r\n");
  const std::string long_text(1000, 'z');
  LineReader reader(write(dir, long_text));
  EXPECT_EQ(reader.head(), long_text.substr(0, LineReader::kHeadBytes));
  EXPECT_EQ(reader.next_line(), long_text);
  EXPECT_EQ(LineReader(write(dir, "")).head(), "");
}

TEST(LineReader, BlankLinesAreReturnedAndCounted) {
  ScratchDir dir("line_reader_blank");
  LineReader reader(write(dir, "a\n\n\nb\n"));
  EXPECT_STREQ(reader.next_line(), "a");
  EXPECT_STREQ(reader.next_line(), "");
  EXPECT_STREQ(reader.next_line(), "");
  EXPECT_STREQ(reader.next_line(), "b");
  EXPECT_EQ(reader.line_number(), 4u);
  EXPECT_EQ(reader.next_line(), nullptr);
  EXPECT_EQ(reader.line_number(), 4u);
}

TEST(LineReader, EmptyFileHasNoLine) {
  ScratchDir dir("line_reader_empty");
  LineReader reader(write(dir, ""));
  EXPECT_EQ(reader.next_line(), nullptr);
  EXPECT_EQ(reader.line_number(), 0u);
  EXPECT_EQ(reader.next_line(), nullptr);
}

TEST(LineReader, LineLengthCountsBytesAfterANul) {
  ScratchDir dir("line_reader_nul");
  LineReader reader(write(dir, std::string("a\0b\n", 4)));
  EXPECT_NE(reader.next_line(), nullptr);
  EXPECT_EQ(reader.line_length(), 3u);
}

TEST(LineReader, LinesLongerThanTheBufferAreReturnedWhole) {
  ScratchDir dir("line_reader_long");
  const std::string a(3'000'001, 'a'), b(5, 'b'), c(1'500'000, 'c');
  EXPECT_EQ(all_lines(write(dir, a + "\n" + b + "\r\n" + c)), (Lines{a, b, c}));
}

TEST(LineReader, LineOfTheLimitLengthIsAccepted) {
  ScratchDir dir("line_reader_at_limit");
  const std::string longest(LineReader::kMaxLineLength, '7');
  const Lines lines = all_lines(write(dir, "x\n" + longest + "\ny\n"));
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[1], longest);
  EXPECT_EQ(lines[2], "y");
}

TEST(LineReader, LineOverTheLimitIsAnErrorWithItsLineNumber) {
  ScratchDir dir("line_reader_over_limit");
  const std::string path =
      write(dir, "x\n\n" + std::string(LineReader::kMaxLineLength + 1, '7') + "\ny\n");
  const InputError e = read_error(path);
  EXPECT_EQ(e.what(), path + ":3: line is longer than 2^24-1 characters; expected a CSV row");
  EXPECT_EQ(e.line(), 3u);
  // The CR of a CRLF counts, as it did in fast-cpp-csv-parser.
  EXPECT_EQ(read_error(write(dir, std::string(LineReader::kMaxLineLength, '7') + "\r\n")).line(),
            1u);
}

TEST(LineReader, EndlessLineIsAnErrorAfterTheLimit) {
  const InputError e = read_error("/dev/zero");
  EXPECT_EQ(e.line(), 1u);
  EXPECT_NE(std::string(e.what()).find("longer than 2^24-1"), std::string::npos) << e.what();
}

// A pipe delivers the data in pieces of any size: here a BOM byte by byte, then lines cut
// anywhere, 12 MB in all.
TEST(LineReader, PipeIsReadLikeAFile) {
  // Should the reader stop early, the writer gets EPIPE instead of a fatal SIGPIPE.
  std::signal(SIGPIPE, SIG_IGN);
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  constexpr int kRows = 600'000;
  std::thread writer([w = fds[1]] {
    auto put = [w](const std::string& s) {
      for (std::size_t done = 0; done < s.size();) {
        const ssize_t n = ::write(w, s.data() + done, s.size() - done);
        if (n <= 0) return;
        done += static_cast<std::size_t>(n);
      }
    };
    for (const char* byte : {"\xEF", "\xBB", "\xBF", "h", "\r", "\n"}) put(byte);
    std::string chunk;
    for (int i = 1; i <= kRows; ++i) {
      chunk += "row " + std::to_string(i) + ",1.5\n";
      if (chunk.size() > 4000u + static_cast<unsigned>(i) % 997) {
        put(chunk.substr(0, 11));
        put(chunk.substr(11));
        chunk.clear();
      }
    }
    put(chunk + "end");
    ::close(w);
  });
  std::vector<std::string> lines;
  std::string head;
  try {
    LineReader reader("/dev/fd/" + std::to_string(fds[0]));
    head = reader.head();
    lines = all_lines(reader);
  } catch (...) {
    ::close(fds[0]);
    writer.join();
    throw;
  }
  ::close(fds[0]);
  writer.join();
  EXPECT_EQ(head.size(), LineReader::kHeadBytes);
  EXPECT_EQ(head.substr(0, 16), "\xEF\xBB\xBFh\r\nrow 1,1.5\n");
  ASSERT_EQ(lines.size(), kRows + 2u);
  EXPECT_EQ(lines.front(), "h");
  EXPECT_EQ(lines[1], "row 1,1.5");
  EXPECT_EQ(lines[kRows], "row " + std::to_string(kRows) + ",1.5");
  EXPECT_EQ(lines.back(), "end");
}

TEST(LineReader, APartFromAnOffsetToAStopHoldsExactlyTheLinesBetween) {
  ScratchDir dir("line_reader_part");
  // Lines longer than a read block, so the stop falls inside one: 300,000 bytes each.
  std::string content;
  for (char c : std::string("abcdef")) content += std::string(299999, c) + "\n";
  const std::string path = write(dir, "\xEF\xBB\xBF" + content);
  LineReader whole(path);
  ASSERT_TRUE(whole.next_line());
  ASSERT_TRUE(whole.stop_at(3 + 2 * 300000));  // before the third line
  const char* second = whole.next_line();
  ASSERT_TRUE(second);
  EXPECT_EQ(std::string(second, whole.line_length()), std::string(299999, 'b'));
  EXPECT_EQ(whole.next_line(), nullptr);
  LineReader part(path, 3 + 2 * 300000);
  EXPECT_EQ(part.head(), "");
  EXPECT_TRUE(part.stop_at(3 + 4 * 300000));
  EXPECT_EQ(all_lines(part), (Lines{std::string(299999, 'c'), std::string(299999, 'd')}));
  LineReader rest(path, 3 + 5 * 300000);
  EXPECT_EQ(all_lines(rest), (Lines{std::string(299999, 'f')}));
}

TEST(LineReader, StopAtBehindWhatIsReadIsRefusedAndChangesNothing) {
  ScratchDir dir("line_reader_stop");
  const std::string path = write(dir, "a\nb\nc\n");
  LineReader reader(path);  // the first read takes the whole small file
  EXPECT_FALSE(reader.stop_at(2));
  EXPECT_EQ(all_lines(reader), (Lines{"a", "b", "c"}));
}

TEST(LineReader, MissingFileIsAnErrorWithTheSystemsReason) {
  ScratchDir dir("line_reader_missing");
  const std::string path = dir / "no.csv";
  try {
    LineReader reader(path);
    ADD_FAILURE() << "opened " << path;
  } catch (const InputError& e) {
    EXPECT_EQ(e.what(), path + ": cannot open file: " + std::strerror(ENOENT));
  }
}

// A failing read is an error, not the end of the data (here: a directory, which opens but
// cannot be read).
TEST(LineReader, ReadErrorIsNotTakenForTheEnd) {
  ScratchDir dir("line_reader_read_error");
  const std::string path = dir.path().string();
  try {
    LineReader reader(path);
    reader.next_line();
    ADD_FAILURE() << "read " << path;
  } catch (const InputError& e) {
    EXPECT_EQ(e.what(), path + ": cannot read file: " + std::strerror(EISDIR));
  }
}

}  // namespace
}  // namespace frictionid::io_detail::line_reader_test
