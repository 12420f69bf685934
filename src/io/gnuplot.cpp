#include "io/gnuplot.hpp"

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>

#include "io/atomic_file.hpp"

namespace frictionid {
namespace {

namespace fs = std::filesystem;

std::optional<std::string> read_whole_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream ss;
  ss << in.rdbuf();
  if (!in.good() && !in.eof()) return std::nullopt;
  return ss.str();
}

bool looks_like_svg(const std::string& s) {
  return s.rfind("<?xml", 0) == 0 || s.rfind("<svg", 0) == 0;
}

// A private directory under the system temp dir, removed with everything in it on scope exit.
class TempDir {
 public:
  TempDir() {
    std::error_code ec;
    const fs::path base = fs::temp_directory_path(ec);
    if (ec) return;
    std::string tmpl = (base / "frictionid-plots-XXXXXX").string();
    if (::mkdtemp(tmpl.data()) != nullptr) path_ = tmpl;
  }
  ~TempDir() {
    if (path_.empty()) return;
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  bool ok() const { return !path_.empty(); }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

}  // namespace

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char ch : s) {
    if (ch == '\'')
      out += "'\\''";
    else
      out += ch;
  }
  return out + "'";
}

bool gnuplot_available() {
  if (std::system(nullptr) == 0) return false;  // no shell to run it with
  const char* path = std::getenv("PATH");
  if (path == nullptr) return false;
  std::string entries = path;
  std::size_t start = 0;
  while (start <= entries.size()) {
    std::size_t end = entries.find(':', start);
    if (end == std::string::npos) end = entries.size();
    std::string d = entries.substr(start, end - start);
    if (d.empty()) d = ".";  // an empty PATH entry means the current directory
    const std::string exe = d + "/gnuplot";
    struct stat sb;
    if (::stat(exe.c_str(), &sb) == 0 && S_ISREG(sb.st_mode) && ::access(exe.c_str(), X_OK) == 0)
      return true;
    start = end + 1;
  }
  return false;
}

std::vector<std::string> render_svgs(const fs::path& dir, const PlotPreparer& prepare) {
  std::vector<std::string> written;
  if (!gnuplot_available()) return written;
  TempDir work;
  if (!work.ok()) return written;
  std::string script =
      "set terminal svg size 800,500 fixed font 'Helvetica,12' noenhanced "
      "background rgb 'white'\n";
  const std::vector<std::string> expected = prepare(work.path(), script);
  if (expected.empty()) return written;
  script += "unset output\n";
  {
    std::ofstream out(work.path() / "plots.gp", std::ios::binary);
    out << script;
    if (!out) return written;
  }
  // -d: ignore the user's ~/.gnuplot so the SVGs do not depend on who runs the tool.
  const std::string cmd =
      "cd " + shell_quote(work.path().string()) + " && gnuplot -d plots.gp >gnuplot.log 2>&1";
  const int status = std::system(cmd.c_str());
  if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return written;
  for (const auto& file : expected) {
    const auto svg = read_whole_file(work.path() / file);
    if (!svg || !looks_like_svg(*svg)) continue;
    try {
      write_file_atomically((dir / file).string(), *svg);
      written.push_back(file);
    } catch (const std::exception&) {
      // Plots are optional; the caller's report files still throw on failure.
    }
  }
  return written;
}

}  // namespace frictionid
