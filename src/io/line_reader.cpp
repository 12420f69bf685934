#include "io/line_reader.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include <frictionid/io/input_error.hpp>

namespace frictionid::io_detail {

namespace {

// The size of the first buffer and so of most reads: large enough that a read(2) call costs
// little per byte, small enough that the bytes just read are still in the cache when parsed.
constexpr std::size_t kBlock = std::size_t{1} << 17;

// The buffer never needs more than the longest line plus room for one read after it.
constexpr std::size_t kMaxCapacity = LineReader::kMaxLineLength + 1 + kBlock;

}  // namespace

LineReader::LineReader(const std::string& path) : path_(path) {
  do fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  while (fd_ < 0 && errno == EINTR);
  if (fd_ < 0)
    throw InputError(path, 0, 0, std::string("cannot open file: ") + std::strerror(errno));
  try {
    capacity_ = kBlock;
    buffer_.reset(new char[capacity_ + 1]);
    // A pipe may deliver fewer bytes at first: read until the head is complete.
    while (end_ < kHeadBytes && fill()) {
    }
    head_.assign(buffer_.get(), std::min(end_, kHeadBytes));
    if (end_ >= 3 && std::memcmp(buffer_.get(), "\xEF\xBB\xBF", 3) == 0) begin_ = 3;
  } catch (...) {
    ::close(fd_);
    throw;
  }
}

LineReader::LineReader(const std::string& path, std::uint64_t begin) : path_(path) {
  do fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  while (fd_ < 0 && errno == EINTR);
  if (fd_ < 0)
    throw InputError(path, 0, 0, std::string("cannot open file: ") + std::strerror(errno));
  if (::lseek(fd_, static_cast<off_t>(begin), SEEK_SET) < 0) {
    const int e = errno;
    ::close(fd_);
    throw InputError(path, 0, 0, std::string("cannot read file: ") + std::strerror(e));
  }
  offset_ = begin;
  capacity_ = kBlock;
  buffer_.reset(new char[capacity_ + 1]);
}

bool LineReader::stop_at(std::uint64_t offset) {
  if (offset_ > offset) return false;
  limit_ = offset;
  return true;
}

LineReader::~LineReader() {
  ::close(fd_);
}

// Moves the unfinished line to the front of the buffer (it is short, except for long lines) and
// doubles the buffer when that line takes more than half of it, so that every read has room
// for at least half a buffer.
void LineReader::make_room() {
  const std::size_t kept = end_ - begin_;
  if (kept > capacity_ / 2 && capacity_ < kMaxCapacity) {
    const std::size_t capacity = std::min(2 * capacity_, kMaxCapacity);
    std::unique_ptr<char[]> bigger(new char[capacity + 1]);
    std::memcpy(bigger.get(), buffer_.get() + begin_, kept);
    buffer_ = std::move(bigger);
    capacity_ = capacity;
  } else if (begin_ > 0) {
    std::memmove(buffer_.get(), buffer_.get() + begin_, kept);
  }
  begin_ = 0;
  end_ = kept;
}

bool LineReader::fill() {
  if (at_eof_) return false;
  make_room();
  const std::size_t room =
      static_cast<std::size_t>(std::min<std::uint64_t>(capacity_ - end_, limit_ - offset_));
  if (room == 0) {  // at stop_at's offset (make_room leaves room otherwise)
    at_eof_ = true;
    return false;
  }
  while (true) {
    const ssize_t n = ::read(fd_, buffer_.get() + end_, room);
    if (n > 0) {
      end_ += static_cast<std::size_t>(n);
      offset_ += static_cast<std::uint64_t>(n);
      return true;
    }
    if (n == 0) {
      at_eof_ = true;
      return false;
    }
    // A read error is not the end of the data: the rows after it would be missing unnoticed.
    if (errno != EINTR)
      throw InputError(path_, 0, 0, std::string("cannot read file: ") + std::strerror(errno));
  }
}

char* LineReader::next_line() {
  char* newline = nullptr;
  while (true) {
    char* const from = buffer_.get() + begin_ + scanned_;
    newline = static_cast<char*>(std::memchr(from, '\n', end_ - begin_ - scanned_));
    if (newline) break;
    scanned_ = end_ - begin_;
    // Already too long: stop before reading the rest of it (it may never end, as /dev/zero).
    if (scanned_ > kMaxLineLength) break;
    if (!fill()) break;
  }
  if (!newline && begin_ == end_) return nullptr;
  ++line_number_;
  char* const line = buffer_.get() + begin_;
  std::size_t length = newline ? static_cast<std::size_t>(newline - line) : end_ - begin_;
  if (length > kMaxLineLength)
    throw InputError(path_, line_number_, 0,
                     "line is longer than 2^24-1 characters; expected a CSV row");
  begin_ += length + (newline ? 1 : 0);
  scanned_ = 0;
  // Without a newline the NUL goes to end_, into the byte allocated beyond capacity_.
  line[length] = '\0';
  if (length > 0 && line[length - 1] == '\r') line[--length] = '\0';
  length_ = length;
  return line;
}

}  // namespace frictionid::io_detail
