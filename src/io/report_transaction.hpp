// One report, written as a whole or not at all.
//
// The user's DIR is a symlink DIR -> .DIR.r-XXXXXX in the same parent. A transaction writes every
// file of the report into a fresh .DIR.r-XXXXXX, then commit() makes a new symlink and rename(2)s
// it over DIR: one atomic step, so a reader, a crash, SIGKILL or a full disk leave either the
// complete old report or the complete new one. The old target is removed after the swap.
// Leftovers of a killed run (.DIR.r-* not linked, .DIR.swap-*) are removed by the next
// transaction, which holds the lock (report_directory_lock.hpp) while it does so.
//
// DIR as a plain directory (reports of earlier versions) is swapped for the symlink with
// renameat2(RENAME_EXCHANGE) where the file system has it (else one non-atomic rename), and only
// when it holds nothing but report files; otherwise commit() refuses rather than delete them.
#pragma once

#include <filesystem>
#include <string>

#include "io/report_directory_lock.hpp"
#include "io/report_location.hpp"
#include "io/stop_check.hpp"

namespace frictionid {

// Throws std::runtime_error (exit 1, like any unusable destination) when a report cannot replace
// DIR: DIR is a file, or a plain directory that holds files that are not part of a report. The CLI
// asks before the fit, so that the user does not wait for a fit whose report would be refused;
// commit() checks again.
void check_report_directory_replaceable(const std::string& dir);

class ReportTransaction {
 public:
  // Locks DIR (waiting; a no-op when this process holds the lock already), cleans up leftovers
  // and creates the staging directory. Throws std::runtime_error (InputError for an unusable
  // DIR name).
  // `stop` (stop_check.hpp) is asked while waiting for the lock and before the swap.
  explicit ReportTransaction(const std::string& dir, StopCheck stop = {});
  // Without commit(), removes the staging directory: DIR stays as it was.
  ~ReportTransaction();
  ReportTransaction(const ReportTransaction&) = delete;
  ReportTransaction& operator=(const ReportTransaction&) = delete;

  // Where to write the report's files (with write_staged_file).
  const std::filesystem::path& staging() const { return staging_; }

  // Swaps the staged report in. Throws Interrupted (stop_check.hpp) when the stop check says
  // so, std::runtime_error when the swap fails; DIR is unchanged in both cases.
  void commit();

 private:
  std::string dir_;
  StopCheck stop_;
  ReportLocation loc_;
  ReportDirectoryLock lock_;
  std::filesystem::path staging_;
  bool committed_ = false;
};

// Writes a new file of a staging directory: no temporary file, no rename and no fsync of its
// own, since nobody sees the directory before commit(), which makes every staged file durable
// with one syncfs(2) before the swap.
void write_staged_file(const std::filesystem::path& path, const std::string& content);

}  // namespace frictionid
