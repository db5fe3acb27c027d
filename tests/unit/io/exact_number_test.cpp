// io::Exact prints a double as fmt's {:.17g} does, byte for byte: final.csv, bodies.csv and
// contacts.csv are read by users' scripts, and their text must not change with the faster
// formatter (issue 12).
#include "io/output/exact_number.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <gtest/gtest.h>
#include <limits>
#include <random>
#include <vector>

namespace tridem::io {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

std::uint64_t bits_of(double d) {
  std::uint64_t b;
  std::memcpy(&b, &d, sizeof b);
  return b;
}

TEST(ExactNumber, PrintsWhatFmtG17Prints) {
  using L = std::numeric_limits<double>;
  // Zeros, short decimals, where {:.17g} turns to exponents, the extremes, the specials.
  std::vector<double> values{0.0, -0.0, 1.0, -1.0, 0.1, 1.0 / 3.0, 2.5};
  for (const double d : {1e15, 1e16, 1e17, 123456789012345678.0, 1e-4, 1e-5, 9.9999999999999995e-5})
    values.push_back(d);
  for (const double d : {L::denorm_min(), L::min(), L::max(), -L::max(), L::epsilon()})
    values.push_back(d);
  for (const double d : {L::infinity(), -L::infinity(), L::quiet_NaN(), -L::quiet_NaN()})
    values.push_back(d);
  std::mt19937_64 rng(17);
  for (int i = 0; i < 200000; ++i) {  // every exponent and sign
    const std::uint64_t bits = rng();
    double d;
    std::memcpy(&d, &bits, sizeof d);
    values.push_back(d);
  }
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 200000; ++i)  // the magnitudes of a simulation's state
    values.push_back(std::ldexp(u(rng), static_cast<int>(rng() % 140) - 70));
  int differ = 0;
  for (const double d : values) {
    const std::string expected = fmt::format("{:.17g}", d);
    const std::string actual = fmt::format(FMT_COMPILE("{}"), Exact{d});
    if (actual != expected && ++differ <= 5)
      ADD_FAILURE() << "bits " << std::hex << bits_of(d) << ": " << actual << " instead of "
                    << expected;
  }
  EXPECT_EQ(differ, 0);
  // And through fmt's run-time format strings, as a row of several.
  EXPECT_EQ(fmt::format("{},{},{}", 7, Exact{0.1}, Exact{-2e-7}),
            "7,0.10000000000000001,-1.9999999999999999e-07");
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem::io
