// SHA-256 against the FIPS 180-4 / NIST example vectors, whatever the pieces the bytes come in.
#include "io/sha256.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>

namespace frictionid::sha256_test {
namespace {

TEST(Sha256, MatchesTheNistExampleVectors) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256_hex(std::string(1'000'000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, PiecesOfAnySizeGiveTheDigestOfTheWhole) {
  std::mt19937 rng(7);
  std::string bytes(5000, '\0');
  for (char& c : bytes) c = static_cast<char>(rng());
  const std::string whole = sha256_hex(bytes);
  for (std::size_t piece : {1u, 3u, 55u, 56u, 63u, 64u, 65u, 1000u}) {
    Sha256 s;
    for (std::size_t at = 0; at < bytes.size(); at += piece)
      s.update(bytes.data() + at, std::min(piece, bytes.size() - at));
    EXPECT_EQ(hex(s.finish()), whole) << piece;
  }
}

// The SHA-NI path (where this processor has it) and the portable code give the same digests,
// for every length around the block boundaries and for pieces that split blocks.
TEST(Sha256, HardwareAndPortableCodeAgree) {
  std::mt19937 rng(11);
  std::string bytes(3 * 64 * 64 + 17, '\0');
  for (char& c : bytes) c = static_cast<char>(rng());
  const auto both = [&](std::size_t length, std::size_t piece) {
    std::string digest[2];
    for (int hardware = 0; hardware < 2; ++hardware) {
      allow_sha256_hardware(hardware == 1);
      Sha256 s;
      for (std::size_t at = 0; at < length; at += piece)
        s.update(bytes.data() + at, std::min(piece, length - at));
      digest[hardware] = hex(s.finish());
    }
    allow_sha256_hardware(true);
    EXPECT_EQ(digest[0], digest[1]) << length << " bytes in pieces of " << piece;
  };
  for (std::size_t length = 0; length <= 3 * 64 + 1; ++length) both(length, length + 1);
  for (std::size_t piece : {1u, 63u, 64u, 65u, 1000u, 4096u}) both(bytes.size(), piece);
  // The NIST vectors both ways.
  for (bool hardware : {false, true}) {
    allow_sha256_hardware(hardware);
    EXPECT_EQ(sha256_hex("abc"),
              "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    EXPECT_EQ(sha256_hex(std::string(1'000'000, 'a')),
              "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
  }
  allow_sha256_hardware(true);
  if (!sha256_hardware_available()) GTEST_SKIP() << "no SHA-NI here: only the portable code ran";
}

TEST(Sha256, MessagesAroundThePaddingBoundaryDiffer) {
  // 55, 56 and 64 bytes put the length in the same block, the next one, or a block of its own.
  EXPECT_NE(sha256_hex(std::string(55, 'x')), sha256_hex(std::string(56, 'x')));
  EXPECT_NE(sha256_hex(std::string(63, 'x')), sha256_hex(std::string(64, 'x')));
}

}  // namespace
}  // namespace frictionid::sha256_test
