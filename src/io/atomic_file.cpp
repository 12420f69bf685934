#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace frictionid {
namespace {

namespace fs = std::filesystem;

// 0, or the errno of the write that failed.
int write_all(int fd, const std::string& content) {
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    done += static_cast<std::size_t>(n);
  }
  return 0;
}

// A FIFO, device or pseudo-file: opened and written in place, as a shell redirection would.
void write_through(const std::string& path, const std::string& content) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0)
    throw std::runtime_error("cannot write " + path +
                             " (not a regular file, written in place): " + std::strerror(errno));
  if (const int err = write_all(fd, content)) {
    ::close(fd);
    throw std::runtime_error("cannot write " + path + " (write): " + std::strerror(err));
  }
  if (::close(fd) != 0)
    throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
}

// /dev/stdout, /proc/self/fd/1 and the like; /dev/shm is an ordinary (memory) file system.
bool under_pseudo_file_system(const std::string& path) {
  return (path.rfind("/dev/", 0) == 0 && path.rfind("/dev/shm/", 0) != 0) ||
         path.rfind("/proc/", 0) == 0;
}

void replace_regular_file(const std::string& path, const std::string& content, Flush flush);

}  // namespace

void write_file_atomically(const std::string& path, const std::string& content, Flush flush) {
  struct stat link_sb, sb;
  const bool exists = ::lstat(path.c_str(), &link_sb) == 0;
  const bool followed = ::stat(path.c_str(), &sb) == 0;
  if (under_pseudo_file_system(path) || (followed && !S_ISREG(sb.st_mode) && !S_ISDIR(sb.st_mode)))
    return write_through(path, content);
  if (exists && S_ISLNK(link_sb.st_mode)) {
    // Keep the link: replace what it names (resolved step by step, so a dangling link names the
    // file to create).
    std::string target = path;
    for (int hops = 0; hops < 40; ++hops) {
      struct stat hop;
      if (::lstat(target.c_str(), &hop) != 0 || !S_ISLNK(hop.st_mode)) break;
      std::error_code ec;
      const fs::path next = fs::read_symlink(target, ec);
      if (ec) break;
      target =
          next.is_absolute() ? next.string() : (fs::path(target).parent_path() / next).string();
    }
    if (under_pseudo_file_system(target)) return write_through(path, content);
    return replace_regular_file(target, content, flush);
  }
  replace_regular_file(path, content, flush);
}

namespace {

void replace_regular_file(const std::string& path, const std::string& content, Flush flush) {
  const fs::path target(path);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::string tmpl = (dir / ("." + target.filename().string() + ".tmp.XXXXXX")).string();
  const int fd = ::mkstemp(tmpl.data());
  if (fd < 0) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
  auto fail = [&](const char* what) {
    const int err = errno;
    ::close(fd);
    std::remove(tmpl.c_str());
    throw std::runtime_error("cannot write " + path + " (" + what + "): " + std::strerror(err));
  };
  if (const int err = write_all(fd, content)) {
    errno = err;
    fail("write");
  }
  if (flush == Flush::Now && ::fsync(fd) != 0) fail("fsync");
  if (::fchmod(fd, 0644) != 0) fail("chmod");
  if (::close(fd) != 0) {
    std::remove(tmpl.c_str());
    throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
  }
  if (std::rename(tmpl.c_str(), path.c_str()) != 0) {
    const int err = errno;
    std::remove(tmpl.c_str());
    throw std::runtime_error("cannot write " + path + ": " + std::strerror(err));
  }
}

}  // namespace
}  // namespace frictionid
