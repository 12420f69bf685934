// Reads a text file line by line into one reused buffer, for the CSV reader: each line is handed
// out in place, NUL-terminated and writable, so the caller can split it without copying.
//
// The file is read with read(2) in blocks, so pipes, FIFOs and /dev/stdin work as well as
// regular files; the buffer grows only while a line does not fit in it. Line ends are LF or CRLF
// (the CR of CRLF is removed); a UTF-8 byte-order mark at the very start is skipped; a last line
// without LF is still a line. These are the rules of fast-cpp-csv-parser's io::LineReader, which
// this replaces, with its limit of 2^24-1 characters per line.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace frictionid::io_detail {

class LineReader {
 public:
  // The longest line accepted, in characters before the LF (a CR of CRLF counts).
  static constexpr std::size_t kMaxLineLength = (std::size_t{1} << 24) - 1;
  // How many bytes head() holds at most.
  static constexpr std::size_t kHeadBytes = 64;

  // Opens `path`; throws InputError "cannot open file: <reason>" when it cannot.
  explicit LineReader(const std::string& path);
  // Reads the regular file `path` from byte offset `begin` (the start of a line) on, as if it
  // began there: no byte-order mark is looked for, head() is empty, line numbers count from
  // that line. For reading one part of a file while other parts are read elsewhere.
  LineReader(const std::string& path, std::uint64_t begin);
  ~LineReader();
  LineReader(const LineReader&) = delete;
  LineReader& operator=(const LineReader&) = delete;

  // The next line without its line end, NUL-terminated and valid until the next call; nullptr
  // at the end of the input. Throws InputError for a line longer than kMaxLineLength or when
  // reading fails.
  char* next_line();

  // The length of the line next_line() returned last (it may contain NUL bytes of its own).
  std::size_t line_length() const { return length_; }

  // The 1-based number of that line; every line counts, blank ones too.
  std::size_t line_number() const { return line_number_; }

  // The first kHeadBytes bytes of the input as they are (a BOM included), or all of a shorter
  // input: what an encoding check looks at. A pipe cannot be opened a second time for them.
  const std::string& head() const { return head_; }

  // Ends the input at file offset `offset` (the start of a line; bytes from there on are
  // another reader's), so that next_line() returns nullptr there. False, and nothing changes,
  // when bytes beyond it have already been read.
  bool stop_at(std::uint64_t offset);

 private:
  bool fill();  // reads more input after end_; false at the end of the input
  void make_room();

  std::string path_;
  std::string head_;
  int fd_ = -1;
  std::unique_ptr<char[]> buffer_;
  std::size_t capacity_ = 0;  // usable bytes; one more is allocated for a final NUL
  std::size_t begin_ = 0;     // the first byte not yet handed out
  std::size_t scanned_ = 0;   // bytes from begin_ on known to hold no LF
  std::size_t end_ = 0;       // one past the last byte read
  bool at_eof_ = false;
  std::uint64_t offset_ = 0;                              // file offset of the byte after end_
  std::uint64_t limit_ = static_cast<std::uint64_t>(-1);  // stop_at's offset
  std::size_t length_ = 0;
  std::size_t line_number_ = 0;
};

}  // namespace frictionid::io_detail
