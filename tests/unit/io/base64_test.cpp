#include "io/output/base64.hpp"
#include "tridem/error.hpp"

#include <gtest/gtest.h>

namespace tridem::io {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

std::vector<std::uint8_t> bytes(std::string_view s) { return {s.begin(), s.end()}; }

TEST(Base64, KnownVectors) {
  EXPECT_EQ(base64_encode(bytes("")), "");
  EXPECT_EQ(base64_encode(bytes("M")), "TQ==");
  EXPECT_EQ(base64_encode(bytes("Ma")), "TWE=");
  EXPECT_EQ(base64_encode(bytes("Man")), "TWFu");
  EXPECT_EQ(base64_encode(bytes("foobar")), "Zm9vYmFy");
}

TEST(Base64, RoundTripsEveryLengthAndByte) {
  for (std::size_t n = 0; n < 40; ++n) {
    std::vector<std::uint8_t> data(n);
    for (std::size_t k = 0; k < n; ++k) data[k] = static_cast<std::uint8_t>(37 * k + 255 - n);
    EXPECT_EQ(base64_decode(base64_encode(data), "test"), data) << n;
  }
  std::vector<std::uint8_t> all(256);
  for (int k = 0; k < 256; ++k) all[k] = static_cast<std::uint8_t>(k);
  EXPECT_EQ(base64_decode(base64_encode(all), "test"), all);
}

TEST(Base64, DecodeSkipsWhitespaceAndAcceptsPaddedRuns) {
  EXPECT_EQ(base64_decode(" TW\nFu\t", "test"), bytes("Man"));
  // Header and data encoded as two runs, as some VTK writers do.
  EXPECT_EQ(base64_decode("TQ==TWFu", "test"), bytes("MMan"));
}

TEST(Base64, DecodeRejectsBadInput) {
  EXPECT_THROW(base64_decode("TW!u", "test"), Error);
  EXPECT_THROW(base64_decode("TWF", "test"), Error);
  EXPECT_THROW(base64_decode("T===", "test"), Error);
  EXPECT_THROW(base64_decode("TW=u", "test"), Error);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem::io
