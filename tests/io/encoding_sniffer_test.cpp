// unsupported_encoding_hint: compressed files and UTF-16/32 are named from their first bytes;
// UTF-8 text (with or without a BOM) and binary noise are left to the CSV reader.
#include "io/encoding_sniffer.hpp"

#include <gtest/gtest.h>

#include <string>

namespace encoding_sniffer_test {
namespace {

using frictionid::unsupported_encoding_hint;

bool says(const std::string& head, const std::string& part) {
  return unsupported_encoding_hint(head).find(part) != std::string::npos;
}

TEST(EncodingSniffer, CompressionIsNamedFromMagicBytes) {
  EXPECT_TRUE(says("\x1F\x8B\x08\x00", "gzip-compressed"));
  EXPECT_TRUE(says("PK\x03\x04rest", "zip archive"));
  EXPECT_TRUE(says("BZh91AY", "bzip2"));
  EXPECT_TRUE(says(std::string("\xFD"
                               "7zXZ\0",
                               6),
                   "xz"));
  EXPECT_TRUE(says("\x28\xB5\x2F\xFD", "zstd"));
}

TEST(EncodingSniffer, ByteOrderMarksNameTheEncoding) {
  EXPECT_TRUE(says("\xFF\xFEv\0_\0", "UTF-16 LE"));
  EXPECT_TRUE(says("\xFE\xFF\0v\0_", "UTF-16 BE"));
  EXPECT_TRUE(says(std::string("\xFF\xFE\0\0v\0\0\0", 8), "UTF-32 LE"));
  EXPECT_TRUE(says(std::string("\0\0\xFE\xFF\0\0\0v", 8), "UTF-32 BE"));
}

TEST(EncodingSniffer, Utf16WithoutAByteOrderMarkIsRecognised) {
  EXPECT_TRUE(says(std::string("v\0_\0x\0,\0o\0", 10), "UTF-16 LE text without"));
  EXPECT_TRUE(says(std::string("\0v\0_\0x\0,\0o", 10), "UTF-16 BE text without"));
}

TEST(EncodingSniffer, Utf8TextAndBinaryNoiseAreNotFlagged) {
  EXPECT_EQ(unsupported_encoding_hint("v_x,v_y,omega,N,R,T_x\n"), "");
  EXPECT_EQ(unsupported_encoding_hint("\xEF\xBB\xBFv_x,omega\n"), "");
  EXPECT_EQ(unsupported_encoding_hint(std::string("\0\x01\x02\x03\x04\x05\x06\x07", 8)), "");
  EXPECT_EQ(unsupported_encoding_hint(""), "");
}

}  // namespace
}  // namespace encoding_sniffer_test
