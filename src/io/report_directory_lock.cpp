#include "io/report_directory_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>

#include "io/report_location.hpp"

namespace frictionid {
namespace {

namespace fs = std::filesystem;

// Lock files this process holds. flock(2) locks belong to an open file description, so a second
// open() and flock() of the same file in this process would wait for itself.
std::mutex& registry_mutex() {
  static std::mutex m;
  return m;
}
std::set<std::string>& registry() {
  static std::set<std::string> held;
  return held;
}

}  // namespace

ReportDirectoryLock::ReportDirectoryLock(
    const std::string& dir, bool wait,
    const std::function<void(const std::string& lock_file)>& on_wait, const StopCheck& stop) {
  const ReportLocation loc = report_location(dir);
  std::error_code ec;
  fs::create_directories(loc.parent, ec);
  if (ec)
    throw std::runtime_error("cannot create " + loc.parent.string() + " for report directory " +
                             dir + ": " + ec.message());
  const fs::path lock_path = loc.sibling("lock");
  fs::path canonical_parent = fs::canonical(loc.parent, ec);
  if (ec) canonical_parent = fs::absolute(loc.parent, ec);
  const std::string key = (canonical_parent / lock_path.filename()).string();
  {
    std::lock_guard<std::mutex> guard(registry_mutex());
    if (registry().count(key)) return;  // nested: the outer lock covers this one
  }
  bool said = false;
  for (;;) {
    fd_ = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0)
      throw std::runtime_error("cannot open lock file " + lock_path.string() + ": " +
                               std::strerror(errno));
    while (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int err = errno;
      if (err == EINTR) continue;
      if (err != EWOULDBLOCK) {
        ::close(fd_);
        throw std::runtime_error("cannot lock " + lock_path.string() + ": " + std::strerror(err));
      }
      if (!wait) {
        ::close(fd_);
        throw DirectoryLocked("another frictionid run is writing report directory " + dir +
                              " (lock " + lock_path.string() + "); without --no-wait it waits");
      }
      if (!said) {
        if (on_wait) on_wait(lock_path.string());
        said = true;
      }
      if (stop && stop()) {
        ::close(fd_);
        throw Interrupted("interrupted while waiting for the lock on report directory " + dir);
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    // The holder before us removes the file before it unlocks it (so that no lock file stays
    // behind): when the path no longer names the file we locked, lock the new one.
    struct stat locked, named;
    if (::fstat(fd_, &locked) == 0 && ::stat(lock_path.c_str(), &named) == 0 &&
        locked.st_dev == named.st_dev && locked.st_ino == named.st_ino)
      break;
    ::close(fd_);
  }
  std::lock_guard<std::mutex> guard(registry_mutex());
  registry().insert(key);
  key_ = key;
  path_ = lock_path.string();
}

ReportDirectoryLock::~ReportDirectoryLock() {
  if (fd_ < 0) return;
  {
    std::lock_guard<std::mutex> guard(registry_mutex());
    registry().erase(key_);
  }
  ::unlink(path_.c_str());  // while still locked: see the constructor
  ::close(fd_);             // releases the flock
}

}  // namespace frictionid
