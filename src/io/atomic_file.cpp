#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>
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

// A FIFO, device or pseudo-file: opened and written in place, as a shell redirection would, and
// appended to: whatever such a target already holds is never truncated or overwritten.
void write_through(const std::string& path, const std::string& content) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
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

// The descriptor this process already has open that `name` stands for: /dev/stdout, /dev/stderr,
// /dev/fd/N, /proc/self/fd/N, /proc/thread-self/fd/N or /proc/<this pid>/fd/N. Opening such a
// name opens the file again, at offset 0 and without the shell's O_APPEND (`>> log` would be
// overwritten from its start); writing to the descriptor itself appends where the shell left it.
std::optional<int> own_descriptor_name(const std::string& name) {
  if (name == "/dev/stdout") return 1;
  if (name == "/dev/stderr") return 2;
  const std::string own = "/proc/" + std::to_string(::getpid()) + "/fd/";
  for (const std::string& prefix : {std::string("/dev/fd/"), std::string("/proc/self/fd/"),
                                    std::string("/proc/thread-self/fd/"), own})
    if (name.size() > prefix.size() && name.compare(0, prefix.size(), prefix) == 0) {
      const std::string digits = name.substr(prefix.size());
      if (digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos)
        return std::nullopt;
      return std::stoi(digits);
    }
  return std::nullopt;
}

// The descriptor `path` reaches, itself or through a chain of symbolic links (followed by name,
// without opening anything), or nullopt.
std::optional<int> own_descriptor(const std::string& path) {
  std::string hop = path;
  for (int hops = 0; hops < 40; ++hops) {
    if (const auto fd = own_descriptor_name(hop)) return fd;
    struct stat sb;
    if (::lstat(hop.c_str(), &sb) != 0 || !S_ISLNK(sb.st_mode)) return std::nullopt;
    std::error_code ec;
    const fs::path next = fs::read_symlink(hop, ec);
    if (ec) return std::nullopt;
    hop = next.is_absolute() ? next.string() : (fs::path(hop).parent_path() / next).string();
  }
  return std::nullopt;
}

// Content written to a descriptor the process inherited, at its current offset, as a shell
// redirection would write it; the descriptor stays open.
void write_to_descriptor(const std::string& path, int fd, const std::string& content) {
  if (const int err = write_all(fd, content))
    throw std::runtime_error("cannot write " + path + " (write): " + std::strerror(err));
}

// /dev/stdout, /proc/self/fd/1 and the like; /dev/shm is an ordinary (memory) file system.
bool under_pseudo_file_system(const std::string& path) {
  return (path.rfind("/dev/", 0) == 0 && path.rfind("/dev/shm/", 0) != 0) ||
         path.rfind("/proc/", 0) == 0;
}

void replace_regular_file(const std::string& path, const std::string& content, Flush flush);

}  // namespace

void write_file_atomically(const std::string& path, const std::string& content, Flush flush) {
  if (const auto fd = own_descriptor(path)) return write_to_descriptor(path, *fd, content);
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
int remove_atomic_leftovers(const std::string& dir) {
  int removed = 0;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec); !ec && it != fs::directory_iterator();
       it.increment(ec)) {
    const std::string name = it->path().filename().string();
    const std::size_t tmp = name.rfind(".tmp.");
    // ".NAME.tmp.XXXXXX": a dot, a name, ".tmp." and mkstemp's six characters.
    if (name.size() < 13 || name[0] != '.' || tmp == std::string::npos || tmp < 2 ||
        name.size() - tmp != 11)
      continue;
    std::error_code status_error;
    if (!it->is_regular_file(status_error)) continue;
    if (fs::remove(it->path(), status_error)) ++removed;
  }
  return removed;
}

}  // namespace frictionid
