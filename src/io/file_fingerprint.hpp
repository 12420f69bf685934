// What identifies the bytes of an input file: its size, modification time and SHA-256, read as a
// stream (memory does not grow with the file). The batch journal records the fingerprint of the
// bytes each fit read, so that a resume refits a run whose file is no longer those bytes.
#pragma once

#include <cstdint>
#include <string>

namespace frictionid {

struct FileFingerprint {
  std::uint64_t size = 0;
  std::int64_t mtime_ns = 0;  // modification time, ns since the epoch
  std::string sha256;         // lower-case hexadecimal

  bool same_bytes(const FileFingerprint& o) const { return size == o.size && sha256 == o.sha256; }
};

// What a file of stat mode `mode` is when it is not a regular file ("a FIFO", "a character
// device", "a block device", "a socket", "a directory", "something else"); "" for a regular file.
std::string non_regular_kind(unsigned mode);

// Throws InputError naming the path: it cannot be opened or read ("permission denied", ...), or
// it is not a regular file (a FIFO or a device has no fixed bytes to fingerprint).
FileFingerprint fingerprint_file(const std::string& path);

// The size and modification time now (no hashing): a file whose size or time changed between two
// calls was changed in between. Throws InputError as fingerprint_file does.
FileFingerprint stat_file(const std::string& path);

}  // namespace frictionid
