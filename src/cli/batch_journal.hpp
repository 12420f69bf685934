// The journal of `frictionid batch`: DIR/journal.jsonl, one JSON line per finished run (its
// label, the hash of its inputs and options, and its summary row), appended and fsynced as each
// run ends. A rerun takes finished runs from it instead of fitting them again, so a killed batch
// loses at most the runs that were in flight; a torn last line (killed mid-write) is ignored.
#pragma once

#include <cstdint>
#include <map>
#include <mutex>
#include <string>

#include <frictionid/io/summary_table.hpp>

namespace frictionid::cli {

class BatchJournal {
 public:
  // Opens (creates) path for appending; fresh = true empties it first (--force).
  // Throws std::runtime_error naming the path when it cannot be opened.
  BatchJournal(const std::string& path, bool fresh);
  ~BatchJournal();
  BatchJournal(const BatchJournal&) = delete;
  BatchJournal& operator=(const BatchJournal&) = delete;

  // The row recorded for label with this key, when the run finished with status ok. Failed runs
  // are fitted again: their cause (a file being written, memory) may be gone.
  const SummaryRow* finished(const std::string& label, std::uint64_t key) const;

  // Appends one line and fsyncs it; safe to call from several threads.
  void record(std::uint64_t key, const SummaryRow& row);

 private:
  struct Entry {
    std::uint64_t key;
    SummaryRow row;
  };
  std::map<std::string, Entry> entries_;  // the last line per label
  std::mutex mutex_;
  int fd_ = -1;
  std::string path_;
};

std::string hex_key(std::uint64_t key);

}  // namespace frictionid::cli
