// The journal of `frictionid batch`: DIR/journal.jsonl, one JSON line per finished run (its
// label, the hash of its inputs and options, the size, time and SHA-256 of the bytes its fit read,
// and its summary row), appended as each run ends. A
// rerun takes finished runs from it instead of fitting them again, so a killed batch loses at
// most the runs that were in flight; a torn last line (killed mid-write) is ignored.
//
// Durability is committed in groups: at most every kJournalSyncInterval the file system holding
// the journal is synced (syncfs), which makes the lines and the runs' report files written
// before them durable together; sync() at the end. A kill loses nothing written, since the page
// cache survives the process; a power cut loses at most the runs of the last interval (a run
// whose line survived without its report file is fitted again, see command_batch.cpp). One sync
// per run would cost one disk flush per run: on 1000 runs of 2000 rows, a third of the wall time.
#pragma once

#include <chrono>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>

#include <frictionid/io/summary_table.hpp>
#include "io/file_fingerprint.hpp"

namespace frictionid::app {

class BatchJournal {
 public:
  // Opens (creates) path for appending; fresh = true empties it first (--force).
  // Throws std::runtime_error naming the path when it cannot be opened.
  BatchJournal(const std::string& path, bool fresh);
  ~BatchJournal();
  BatchJournal(const BatchJournal&) = delete;
  BatchJournal& operator=(const BatchJournal&) = delete;

  // The row recorded for label with this key, when the run finished with status ok and its fit
  // read the bytes `input` now holds. Failed runs are fitted again: their cause (a file being
  // written, memory) may be gone. `changed`, when given, is set when the line is there but its
  // fit read other bytes (the file was replaced while the batch ran, then restored).
  const SummaryRow* finished(const std::string& label, std::uint64_t key,
                             const FileFingerprint& input, bool* changed = nullptr) const;

  // Appends one line, with the fingerprint of the bytes the fit read, and syncs when the last
  // sync is kJournalSyncInterval old; safe to call from several threads.
  void record(std::uint64_t key, const SummaryRow& row, const FileFingerprint& read);

  // Makes every line and every file written before it on the journal's file system durable.
  void sync();

 private:
  struct Entry {
    std::uint64_t key;
    SummaryRow row;
    std::string sha256;  // of the bytes its fit read; empty in a line of an earlier version
  };
  void sync_locked();  // with mutex_ held

  std::map<std::string, Entry> entries_;  // the last line per label
  std::mutex mutex_;
  int fd_ = -1;
  std::string path_;
  std::chrono::steady_clock::time_point last_sync_ = std::chrono::steady_clock::now();
};

inline constexpr std::chrono::milliseconds kJournalSyncInterval{500};

std::string hex_key(std::uint64_t key);

}  // namespace frictionid::app
