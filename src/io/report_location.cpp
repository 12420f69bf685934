#include "io/report_location.hpp"

#include <frictionid/io/input_error.hpp>
#include "io/text.hpp"

namespace frictionid {

ReportLocation report_location(const std::string& dir) {
  namespace fs = std::filesystem;
  fs::path p = fs::path(dir).lexically_normal();
  if (!p.has_filename() && p.has_parent_path() && p.parent_path() != p) p = p.parent_path();
  const std::string name = p.filename().string();
  if (name.empty() || name == "." || name == "..")
    throw InputError("report directory " + text::shown(dir) +
                     ": name a directory of its own (e.g. " + text::shown(dir + "/report") +
                     "); the report replaces that directory as a whole");
  return ReportLocation{p.has_parent_path() ? p.parent_path() : fs::path("."), name};
}

}  // namespace frictionid
