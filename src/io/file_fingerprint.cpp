#include "io/file_fingerprint.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <vector>

#include <frictionid/io/input_error.hpp>
#include "io/sha256.hpp"

namespace frictionid {

namespace {

std::string reason(int err) {
  return err == EACCES ? "permission denied" : std::strerror(err);
}

FileFingerprint from_stat(const std::string& path, const struct stat& sb) {
  if (const std::string kind = non_regular_kind(sb.st_mode); !kind.empty())
    throw InputError(
        path, 0, 0,
        kind == "something else" ? "not a regular file" : "not a regular file (" + kind + ")");
  FileFingerprint f;
  f.size = static_cast<std::uint64_t>(sb.st_size);
  f.mtime_ns = static_cast<std::int64_t>(sb.st_mtim.tv_sec) * 1'000'000'000 + sb.st_mtim.tv_nsec;
  return f;
}

}  // namespace

std::string non_regular_kind(unsigned mode) {
  if (S_ISREG(mode)) return "";
  return S_ISFIFO(mode)   ? "a FIFO"
         : S_ISCHR(mode)  ? "a character device"
         : S_ISBLK(mode)  ? "a block device"
         : S_ISSOCK(mode) ? "a socket"
         : S_ISDIR(mode)  ? "a directory"
                          : "something else";
}

FileFingerprint stat_file(const std::string& path) {
  struct stat sb;
  if (::stat(path.c_str(), &sb) != 0) throw InputError(path, 0, 0, reason(errno));
  return from_stat(path, sb);
}

FileFingerprint fingerprint_file(const std::string& path) {
  // Checked before opening: opening a FIFO would wait for a writer.
  (void)stat_file(path);
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw InputError(path, 0, 0, "cannot open: " + reason(errno));
  struct stat sb;
  if (::fstat(fd, &sb) != 0) {
    const int err = errno;
    ::close(fd);
    throw InputError(path, 0, 0, reason(err));
  }
  FileFingerprint f;
  try {
    f = from_stat(path, sb);
  } catch (...) {
    ::close(fd);
    throw;
  }
  Sha256 hash;
  std::uint64_t total = 0;
  std::vector<char> buffer(std::size_t{1} << 16);
  for (;;) {
    const ssize_t n = ::read(fd, buffer.data(), buffer.size());
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      const int err = errno;
      ::close(fd);
      throw InputError(path, 0, 0, "cannot read: " + reason(err));
    }
    hash.update(buffer.data(), static_cast<std::size_t>(n));
    total += static_cast<std::uint64_t>(n);
  }
  ::close(fd);
  f.size = total;  // the bytes hashed, should the file have grown meanwhile
  f.sha256 = hex(hash.finish());
  return f;
}

}  // namespace frictionid
