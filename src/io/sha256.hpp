// SHA-256 (FIPS 180-4), written here so that frictionid can name the exact bytes it read (batch
// journal, report traceability) without a cryptography library. On x86-64 processors with the
// SHA extensions (SHA-NI) the blocks go through them, about six times faster than the portable
// code (which a FRICTIONID_PORTABLE build, another architecture or an older processor runs);
// both give the same digest.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace frictionid {

class Sha256 {
 public:
  Sha256();
  void update(const void* data, std::size_t size);
  // The digest of everything given to update; the object is spent afterwards.
  std::array<std::uint8_t, 32> finish();

 private:
  void blocks(const std::uint8_t* p, std::size_t n);  // n whole 64-byte blocks
  std::array<std::uint32_t, 8> h_;
  std::array<std::uint8_t, 64> buffer_{};
  std::size_t buffered_ = 0;
  std::uint64_t bytes_ = 0;
};

// Whether this build and this processor have the SHA-NI path: x86-64 with the SHA extensions,
// and not a FRICTIONID_PORTABLE build.
bool sha256_hardware_available();

// Whether Sha256 may use the SHA-NI path where it is available; on unless turned off. Off: the
// portable code, the same digests. Process-wide; for tests and comparisons.
void allow_sha256_hardware(bool allow);

// Lower-case hexadecimal of a digest.
std::string hex(const std::array<std::uint8_t, 32>& digest);

// The hexadecimal SHA-256 of `bytes`.
std::string sha256_hex(std::string_view bytes);

}  // namespace frictionid
