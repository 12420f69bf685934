#include "io/report_transaction.hpp"

#include <fcntl.h>
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <utility>
#include <vector>

namespace frictionid {
namespace {

namespace fs = std::filesystem;

// err 0: the message says it all.
[[noreturn]] void fail(const std::string& what, int err) {
  throw std::runtime_error(err ? what + ": " + std::strerror(err) : what);
}

// Makes the directory's entries (new files, a rename) durable before the next step relies on
// them.
void sync_directory(const fs::path& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) fail("cannot open " + dir.string(), errno);
  const int rc = ::fsync(fd);
  const int err = errno;
  ::close(fd);
  if (rc != 0 && err != EINVAL) fail("cannot sync " + dir.string(), err);
}

std::string link_target(const fs::path& link) {
  std::error_code ec;
  const fs::path t = fs::read_symlink(link, ec);
  return ec ? std::string() : t.string();
}

// A file a report of an earlier version may hold: what write_report and write_compare_report
// make, and the temporary files of an interrupted write. Subdirectories (compare's per-model
// reports) are checked one level down.
bool is_report_file(const fs::directory_entry& e, int depth) {
  const std::string name = e.path().filename().string();
  std::error_code ec;
  if (e.is_symlink(ec)) return false;
  if (e.is_directory(ec)) {
    if (depth > 0) return false;
    for (const auto& sub : fs::directory_iterator(e.path(), ec))
      if (!is_report_file(sub, depth + 1)) return false;
    return !ec;
  }
  if (!e.is_regular_file(ec)) return false;
  if (name.size() > 1 && name[0] == '.' && name.find(".tmp.") != std::string::npos) return true;
  for (const char* ext : {".json", ".md", ".svg", ".html"}) {
    const std::string x = ext;
    if (name.size() > x.size() && name.compare(name.size() - x.size(), x.size(), x) == 0)
      return true;
  }
  return false;
}

std::string first_foreign_file(const fs::path& dir) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (!is_report_file(e, 0)) return e.path().filename().string();
  if (ec) return "(unreadable: " + ec.message() + ")";
  return {};
}

std::string not_replaceable_reason(const std::string& dir, const fs::path& path) {
  struct stat st;
  if (::lstat(path.c_str(), &st) != 0 || S_ISLNK(st.st_mode)) return {};
  if (!S_ISDIR(st.st_mode))
    return "cannot write report " + dir + ": it exists and is not a directory";
  const std::string foreign = first_foreign_file(path);
  if (foreign.empty()) return {};
  return "report directory " + dir + " holds '" + foreign +
         "', which is not part of a report; the report replaces the directory as a whole, so "
         "choose a new or empty directory";
}

}  // namespace

void check_report_directory_replaceable(const std::string& dir) {
  const std::string why = not_replaceable_reason(dir, report_location(dir).path());
  if (!why.empty()) throw std::runtime_error(why);
}

ReportTransaction::ReportTransaction(const std::string& dir, StopCheck stop)
    : dir_(dir),
      stop_(std::move(stop)),
      loc_(report_location(dir)),
      lock_(dir, /*wait=*/true, {}, stop_) {
  // Leftovers of a run killed before or during its swap; the lock keeps live runs out.
  const std::string current = link_target(loc_.path());
  const std::string staged_prefix = "." + loc_.name + ".r-";
  const std::string swap_prefix = "." + loc_.name + ".swap-";
  std::error_code ec;
  std::vector<fs::path> stale;
  for (const auto& e : fs::directory_iterator(loc_.parent, ec)) {
    const std::string n = e.path().filename().string();
    if ((n.rfind(staged_prefix, 0) == 0 && n != current) || n.rfind(swap_prefix, 0) == 0)
      stale.push_back(e.path());
  }
  for (const auto& p : stale) fs::remove_all(p, ec);

  std::string tmpl = loc_.sibling("r-XXXXXX").string();
  if (::mkdtemp(tmpl.data()) == nullptr)
    fail("cannot create a directory for report " + dir + " in " + loc_.parent.string(), errno);
  staging_ = tmpl;
  ::chmod(staging_.c_str(), 0755);  // mkdtemp makes 0700; a report is for reading
}

ReportTransaction::~ReportTransaction() {
  if (committed_ || staging_.empty()) return;
  std::error_code ec;
  fs::remove_all(staging_, ec);
}

void write_staged_file(const fs::path& path, const std::string& content) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) fail("cannot write " + path.string(), errno);
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int err = errno;
      ::close(fd);
      fail("cannot write " + path.string(), err);
    }
    done += static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0) fail("cannot write " + path.string(), errno);
}

void ReportTransaction::commit() {
  if (stop_ && stop_()) throw Interrupted("interrupted before report " + dir_ + " was replaced");
  // Every staged file, directory entries included, durable in one call rather than one fsync
  // per file: the swap below must never expose a report whose files are not on disk.
  {
    const int fd = ::open(staging_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) fail("cannot open " + staging_.string(), errno);
    const int rc = ::syncfs(fd);
    const int err = errno;
    ::close(fd);
    if (rc != 0) fail("cannot sync " + staging_.string(), err);
  }
  sync_directory(staging_);
  const std::string target = staging_.filename().string();
  const std::string suffix = target.substr(target.rfind('-') + 1);
  const fs::path link = loc_.sibling("swap-" + suffix);
  const fs::path final_path = loc_.path();
  if (::symlink(target.c_str(), link.c_str()) != 0)
    fail("cannot write report " + dir_ + " (symlink " + link.string() + ")", errno);
  auto undo = [&](const std::string& what, int err) {
    ::unlink(link.c_str());
    fail(what, err);
  };

  struct stat st;
  fs::path old_to_remove;
  if (::lstat(final_path.c_str(), &st) != 0) {
    if (errno != ENOENT) undo("cannot read " + dir_, errno);
    if (::rename(link.c_str(), final_path.c_str()) != 0) undo("cannot write report " + dir_, errno);
  } else if (S_ISLNK(st.st_mode)) {
    const std::string old = link_target(final_path);
    if (::rename(link.c_str(), final_path.c_str()) != 0) undo("cannot write report " + dir_, errno);
    // Only our own staging directories, never what a user's symlink points at.
    if (old.rfind("." + loc_.name + ".r-", 0) == 0 && old.find('/') == std::string::npos)
      old_to_remove = loc_.parent / old;
  } else if (S_ISDIR(st.st_mode)) {
    const std::string foreign = first_foreign_file(final_path);
    if (!foreign.empty())
      undo("report directory " + dir_ + " holds '" + foreign +
               "', which is not part of a report; the report replaces the directory as a whole, "
               "so choose a new or empty directory",
           0);
    // One-time change of a plain directory (earlier versions) into the symlink.
    if (::renameat2(AT_FDCWD, link.c_str(), AT_FDCWD, final_path.c_str(), RENAME_EXCHANGE) == 0) {
      old_to_remove = link;  // now the old directory
    } else {
      const int err = errno;
      if (err != EINVAL && err != ENOSYS && err != EOPNOTSUPP)
        undo("cannot write report " + dir_, err);
      const fs::path aside = loc_.sibling("swap-old-" + suffix);
      if (::rename(final_path.c_str(), aside.c_str()) != 0) undo("cannot move " + dir_, errno);
      if (::rename(link.c_str(), final_path.c_str()) != 0) {
        const int e2 = errno;
        ::rename(aside.c_str(), final_path.c_str());
        undo("cannot write report " + dir_, e2);
      }
      old_to_remove = aside;
    }
  } else {
    undo("cannot write report " + dir_ + ": it exists and is not a directory", 0);
  }
  committed_ = true;
  try {
    sync_directory(loc_.parent);
  } catch (const std::runtime_error&) {
    // The swap is done; a failed sync only weakens durability across a power loss.
  }
  if (!old_to_remove.empty()) {
    std::error_code ec;
    fs::remove_all(old_to_remove, ec);
  }
}

}  // namespace frictionid
