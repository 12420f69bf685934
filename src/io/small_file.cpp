#include "io/small_file.hpp"

#include <filesystem>
#include <fstream>

#include <frictionid/io/input_error.hpp>

namespace frictionid::io {

std::string read_small_file(const std::string& path, const std::string& expected_file,
                            const std::string& what, const std::string& expected_content) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path, 0, 0, "is a directory; expected " + expected_file);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, 0, "cannot open the " + what);
  constexpr std::size_t kMaxBytes = std::size_t{16} << 20;
  std::string content(kMaxBytes + 1, '\0');
  in.read(content.data(), static_cast<std::streamsize>(content.size()));
  content.resize(static_cast<std::size_t>(in.gcount()));
  if (content.size() > kMaxBytes)
    throw InputError(path, 0, 0, "is larger than 16 MiB; expected " + expected_content);
  return content;
}

}  // namespace frictionid::io
