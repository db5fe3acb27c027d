// io::Exact prints a double as the shortest text that reads back the same double: the
// CSVs' numbers (final.csv, bodies.csv, contacts.csv), which users' scripts read, are the
// simulator's doubles exactly, in fewer bytes and less time than %.17g's (issue 12).
// io::ExactFloat prints a float32 (the float precision's contact numbers) as the fewest
// digits that read back the same float32.
#include "io/output/exact_number.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <gtest/gtest.h>
#include <limits>
#include <random>
#include <vector>

namespace tridem::io {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

/// `text` read as a T.
template <class T>
T read(const std::string& text) {
  if constexpr (sizeof(T) == sizeof(float))
    return std::strtof(text.c_str(), nullptr);
  else
    return std::strtod(text.c_str(), nullptr);
}

/// How many of `values` Shortest<T> prints as a text that does not read back the same T, or
/// that is longer than %.Pg's with the fewest digits P that read it back (a large integer
/// may print all its digits, as "1200" does, where that is no longer); the first five are
/// reported.
template <class T>
int not_shortest(const std::vector<T>& values) {
  int differ = 0;
  for (const T v : values) {
    const std::string text = fmt::format(FMT_COMPILE("{}"), Shortest<T>{v});
    int fewest = 1;
    while (read<T>(fmt::format("{:.{}g}", v, fewest)) != v) ++fewest;
    const std::string shortest_g = fmt::format("{:.{}g}", v, fewest);
    if ((read<T>(text) != v || text.size() > shortest_g.size()) && ++differ <= 5)
      ADD_FAILURE() << fmt::format("{:.17g}", v) << ": " << text << " against " << shortest_g;
  }
  return differ;
}

TEST(ExactNumber, IsTheShortestTextThatReadsBackTheSameDouble) {
  using L = std::numeric_limits<double>;
  // Zeros, short decimals, where the shortest form turns to exponents, the extremes.
  std::vector<double> values{0.0, -0.0, 1.0, -1.0, 0.1, 1.0 / 3.0, 2.5, 1200.0};
  for (const double d : {1e15, 1e16, 1e17, 123456789012345678.0, 1e-4, 1e-5, 9.9999999999999995e-5})
    values.push_back(d);
  for (const double d : {L::denorm_min(), L::min(), L::max(), -L::max(), L::epsilon()})
    values.push_back(d);
  std::mt19937_64 rng(17);
  for (int i = 0; i < 200000; ++i) {  // every exponent and sign
    const std::uint64_t bits = rng();
    double d;
    std::memcpy(&d, &bits, sizeof d);
    if (std::isfinite(d)) values.push_back(d);
  }
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 200000; ++i)  // the magnitudes of a simulation's state
    values.push_back(std::ldexp(u(rng), static_cast<int>(rng() % 140) - 70));
  for (int i = 0; i < 2000; ++i)  // short decimals, as a scene's inputs are
    values.push_back(static_cast<double>(rng() % 100000) / 1000.0);
  EXPECT_EQ(not_shortest(values), 0);
  // The specials as %.17g printed them.
  for (const double d : {L::infinity(), -L::infinity(), L::quiet_NaN(), -L::quiet_NaN()})
    EXPECT_EQ(fmt::format("{}", Exact{d}), fmt::format("{:.17g}", d));
  // And through fmt's run-time format strings, as a row of several.
  EXPECT_EQ(fmt::format("{},{},{},{}", 7, Exact{0.1}, Exact{-2e-7}, Exact{1.0 / 3.0}),
            "7,0.1,-2e-07,0.3333333333333333");
}

TEST(ExactNumber, FloatIsTheFewestDigitsThatReadBackTheSameFloat32) {
  using L = std::numeric_limits<float>;
  std::vector<float> values{0.0f, -0.0f, 1.0f, -1.0f, 0.1f, 1.0f / 3.0f, 2.5f, 1e-5f, 3e7f};
  for (const float f : {L::denorm_min(), L::min(), L::max(), -L::max(), L::epsilon()})
    values.push_back(f);
  std::mt19937 rng(9);
  for (int i = 0; i < 200000; ++i) {  // every exponent and sign
    const auto bits = static_cast<std::uint32_t>(rng());
    float f;
    std::memcpy(&f, &bits, sizeof f);
    if (std::isfinite(f)) values.push_back(f);
  }
  EXPECT_EQ(not_shortest(values), 0);
  // Never longer than 9 significant digits (what any float32 needs) would write it.
  int longer = 0;
  for (const float f : values)
    longer += fmt::format("{}", ExactFloat{f}).size() > fmt::format("{:.9g}", f).size();
  EXPECT_EQ(longer, 0);
  // The shortest: 0.1f is "0.1", not its double's 0.10000000149011612.
  EXPECT_EQ(fmt::format("{},{},{}", ExactFloat{0.1f}, ExactFloat{-2e-7f}, ExactFloat{1.5f}),
            "0.1,-2e-07,1.5");
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem::io
