// Recognises, from its first bytes, a file that is not UTF-8 text: compressed (gzip, zip, bzip2,
// xz, zstd, by their magic bytes) or UTF-16/UTF-32 (by the byte-order mark, or for UTF-16
// without one, by a NUL in every other byte). Readers call it before parsing, so such a file
// gets a message that names the encoding instead of "missing column".
#pragma once

#include <string>
#include <string_view>

namespace frictionid {

// What the file is and what to do about it (e.g. "the file is gzip-compressed (it starts with
// the bytes 1F 8B); decompress it first"), or "" for text that may be UTF-8.
std::string unsupported_encoding_hint(std::string_view head);

// The first `bytes` bytes of the file at path ("" when it cannot be read).
std::string file_head(const std::string& path, std::size_t bytes = 64);

}  // namespace frictionid
