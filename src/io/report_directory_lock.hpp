// An advisory lock (flock(2)) for one report directory DIR, held for a whole run so that two
// fits into the same DIR cannot interleave. The lock
// file is the sibling .DIR.lock: DIR itself changes identity on every swap
// (report_transaction.hpp). The holder removes the lock file before it unlocks, and a waiter
// that then gets the lock checks that the path still names the file it locked (else it locks
// the new one), so no lock file stays behind and no two runs hold "the" lock at once.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>

#include "io/stop_check.hpp"

namespace frictionid {

// Another process holds the lock and the caller asked not to wait.
class DirectoryLocked : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ReportDirectoryLock {
 public:
  // wait = false: throws DirectoryLocked at once when another process holds the lock.
  // wait = true: calls on_wait(lock file) once, when it starts waiting (the front end says so
  // where its user looks; io prints nothing), and waits, polling `stop` (stop_check.hpp), so
  // Ctrl-C still ends the wait with Interrupted. Creates DIR's parent when
  // missing. Taking the lock again in a process that already holds it is a no-op (write_report
  // locks on its own; the CLI locks earlier, before the fit).
  ReportDirectoryLock(const std::string& dir, bool wait,
                      const std::function<void(const std::string& lock_file)>& on_wait = {},
                      const StopCheck& stop = {});
  ~ReportDirectoryLock();
  ReportDirectoryLock(const ReportDirectoryLock&) = delete;
  ReportDirectoryLock& operator=(const ReportDirectoryLock&) = delete;

 private:
  int fd_ = -1;
  std::string key_;   // lock file path in this process's registry; empty for a nested lock
  std::string path_;  // the lock file, as opened
};

}  // namespace frictionid
