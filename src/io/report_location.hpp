// Where a report directory DIR lives: its parent and its name. The report itself is the symlink
// DIR -> .DIR.r-XXXXXX in the parent (report_transaction.hpp), the lock is .DIR.lock next to it
// (report_directory_lock.hpp), so everything is named from these two parts.
#pragma once

#include <filesystem>
#include <string>

namespace frictionid {

struct ReportLocation {
  std::filesystem::path parent;  // "." for a bare name
  std::string name;              // the last component of DIR, never empty, "." or ".."

  std::filesystem::path path() const { return parent / name; }
  // Sibling entries of the report (".<name>.<suffix>").
  std::filesystem::path sibling(const std::string& suffix) const {
    return parent / ("." + name + "." + suffix);
  }
};

// Throws InputError when DIR has no usable last component ("", ".", "..", "/").
ReportLocation report_location(const std::string& dir);

}  // namespace frictionid
