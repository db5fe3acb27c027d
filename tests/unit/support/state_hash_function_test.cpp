// The state hash of support/state_hash.hpp is the FNV-1a it documents, over a byte stream
// that is the same on every host.
#include "support/state_hash.hpp"

#include <gtest/gtest.h>
#include <string>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

// The hash is the documented FNV-1a: its published test vectors.
TEST(StateHashFunction, IsFnv1a64) {
  test::Fnv1a64 empty;
  EXPECT_EQ(empty.value(), 0xcbf29ce484222325ULL);
  test::Fnv1a64 a;
  a.add(static_cast<unsigned char>('a'));
  EXPECT_EQ(a.value(), 0xaf63dc4c8601ec8cULL);
  test::Fnv1a64 foobar;
  for (char ch : std::string("foobar")) foobar.add(static_cast<unsigned char>(ch));
  EXPECT_EQ(foobar.value(), 0x85944171f73967e8ULL);
}

// Values enter little-endian at their own width, so the stream is the same on any host.
TEST(StateHashFunction, WritesValuesLittleEndianAtTheirWidth) {
  test::Fnv1a64 as_value, as_bytes;
  as_value.add(std::int32_t{0x01020304});
  for (unsigned b : {0x04u, 0x03u, 0x02u, 0x01u}) as_bytes.add(static_cast<unsigned char>(b));
  EXPECT_EQ(as_value.value(), as_bytes.value());
  test::Fnv1a64 one, one_bits;
  one.add(1.0);
  one_bits.add(std::uint64_t{0x3ff0000000000000ULL});
  EXPECT_EQ(one.value(), one_bits.value());
  test::Fnv1a64 zero, negative_zero;
  zero.add(0.0);
  negative_zero.add(-0.0);
  EXPECT_NE(zero.value(), negative_zero.value());
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
