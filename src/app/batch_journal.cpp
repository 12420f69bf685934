#include "app/batch_journal.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace frictionid::app {

std::string hex_key(std::uint64_t key) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(key));
  return buf;
}

BatchJournal::BatchJournal(const std::string& path, bool fresh) : path_(path) {
  bool torn = false;  // the last line has no newline: a kill cut it short
  if (!fresh) {
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
      torn = in.eof();
      try {
        const auto j = nlohmann::ordered_json::parse(line);
        const auto key = std::stoull(j.at("key").get<std::string>(), nullptr, 16);
        SummaryRow row = summary_row_from_json(j.at("row"));
        const std::string label = row.label;
        const auto input = j.find("input");
        std::string sha256 = input != j.end() && input->contains("sha256")
                                 ? input->at("sha256").get<std::string>()
                                 : std::string();
        entries_.insert_or_assign(label, Entry{key, std::move(row), std::move(sha256)});
      } catch (const std::exception&) {
        // A line cut short by a kill, or not ours: that run is simply fitted again.
      }
    }
  }
  fd_ =
      ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC | (fresh ? O_TRUNC : 0), 0644);
  if (fd_ < 0)
    throw std::runtime_error(path + ": cannot open the batch journal: " + std::strerror(errno));
  // End the torn line, so that the next record starts a line of its own.
  if (torn && ::write(fd_, "\n", 1) != 1)
    throw std::runtime_error(path + ": cannot write the batch journal: " + std::strerror(errno));
}

BatchJournal::~BatchJournal() {
  if (fd_ >= 0) ::close(fd_);
}

const SummaryRow* BatchJournal::finished(const std::string& label, std::uint64_t key,
                                         const FileFingerprint& input, bool* changed) const {
  if (changed) *changed = false;
  const auto it = entries_.find(label);
  if (it == entries_.end() || it->second.key != key || !it->second.row.ok) return nullptr;
  if (it->second.sha256 != input.sha256) {
    if (changed) *changed = true;
    return nullptr;
  }
  return &it->second.row;
}

void BatchJournal::record(std::uint64_t key, const SummaryRow& row, const FileFingerprint& read) {
  nlohmann::ordered_json j;
  j["label"] = row.label;
  j["key"] = hex_key(key);
  j["input"] = {{"size", read.size}, {"mtime_ns", read.mtime_ns}, {"sha256", read.sha256}};
  j["row"] = summary_row_json(row);
  // One write of a whole line: with O_APPEND, lines of concurrent writers never interleave.
  const std::string line =
      j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
  std::lock_guard<std::mutex> guard(mutex_);
  std::size_t done = 0;
  while (done < line.size()) {
    const ssize_t n = ::write(fd_, line.data() + done, line.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0)
      throw std::runtime_error(path_ + ": cannot write the batch journal: " + std::strerror(errno));
    done += static_cast<std::size_t>(n);
  }
  if (std::chrono::steady_clock::now() - last_sync_ >= kJournalSyncInterval) sync_locked();
}

void BatchJournal::sync() {
  std::lock_guard<std::mutex> guard(mutex_);
  sync_locked();
}

void BatchJournal::sync_locked() {
  if (::syncfs(fd_) != 0)
    throw std::runtime_error(path_ + ": cannot sync the batch journal: " + std::strerror(errno));
  last_sync_ = std::chrono::steady_clock::now();
}

}  // namespace frictionid::app
