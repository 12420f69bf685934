#include "io/encoding_sniffer.hpp"

#include <fstream>

namespace frictionid {
namespace {

bool starts(std::string_view s, std::string_view prefix) {
  return s.substr(0, prefix.size()) == prefix;
}

// Text in UTF-16 without a byte-order mark: ASCII characters with a NUL byte before (BE) or
// after (LE) each of them, over the first 8 bytes at least.
bool utf16_pattern(std::string_view s, bool little_endian) {
  if (s.size() < 8) return false;
  const std::size_t n = s.size() & ~std::size_t{1};
  for (std::size_t i = 0; i < n; i += 2) {
    const unsigned char text = static_cast<unsigned char>(s[little_endian ? i : i + 1]);
    const unsigned char zero = static_cast<unsigned char>(s[little_endian ? i + 1 : i]);
    if (zero != 0 || text == 0 || text >= 0x80) return false;
  }
  return true;
}

}  // namespace

std::string unsupported_encoding_hint(std::string_view head) {
  struct Magic {
    std::string_view bytes, shown, what, action;
  };
  static const Magic kMagic[] = {
      {"\x1F\x8B", "1F 8B", "gzip-compressed", "decompress it first (e.g. gunzip)"},
      {"PK\x03\x04", "50 4B 03 04", "a zip archive", "extract the CSV from it first"},
      {"BZh", "42 5A 68", "bzip2-compressed", "decompress it first (e.g. bunzip2)"},
      {std::string_view("\xFD"
                        "7zXZ\0",
                        6),
       "FD 37 7A 58 5A 00", "xz-compressed", "decompress it first (e.g. unxz)"},
      {"\x28\xB5\x2F\xFD", "28 B5 2F FD", "zstd-compressed", "decompress it first (e.g. unzstd)"},
      {std::string_view("\xFF\xFE\0\0", 4), "FF FE 00 00", "UTF-32 LE text", "save it as UTF-8"},
      {std::string_view("\0\0\xFE\xFF", 4), "00 00 FE FF", "UTF-32 BE text", "save it as UTF-8"},
      {"\xFF\xFE", "FF FE", "UTF-16 LE text", "save it as UTF-8"},
      {"\xFE\xFF", "FE FF", "UTF-16 BE text", "save it as UTF-8"},
  };
  for (const Magic& m : kMagic)
    if (starts(head, m.bytes))
      return "the file is " + std::string(m.what) + " (it starts with the bytes " +
             std::string(m.shown) + "); " + std::string(m.action) + ": expected a UTF-8 CSV file";
  for (const bool le : {true, false})
    if (utf16_pattern(head, le))
      return std::string("the file seems to be UTF-16 ") + (le ? "LE" : "BE") +
             " text without a byte-order mark (every other byte is NUL); save it as UTF-8: "
             "expected a UTF-8 CSV file";
  return {};
}

std::string file_head(const std::string& path, std::size_t bytes) {
  std::ifstream in(path, std::ios::binary);
  std::string head(bytes, '\0');
  in.read(head.data(), static_cast<std::streamsize>(bytes));
  head.resize(in ? bytes : static_cast<std::size_t>(in.gcount()));
  return head;
}

}  // namespace frictionid
