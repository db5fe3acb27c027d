// Snapshot::resize sizes its arrays side by side on the threads once they are large: every
// per-particle array, the reals, material and motion alike, ends at the new size, keeps
// its values and zeroes the new entries, growing and shrinking.
#include "tridem/snapshot.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

/// Every real array of the snapshot, with its name for the failure message.
std::vector<std::pair<const char*, std::vector<double>*>> real_arrays(Snapshot& s) {
  std::vector<std::pair<const char*, std::vector<double>*>> out;
  Snapshot::for_each_field([&](auto field) {
    for_each_array(s.column(field),
                   [&](std::vector<double>& v, int) { out.emplace_back("field", &v); });
  });
  out.insert(out.end(), {{"x1", &s.x1},
                         {"y1", &s.y1},
                         {"x2", &s.x2},
                         {"y2", &s.y2},
                         {"x3", &s.x3},
                         {"y3", &s.y3},
                         {"mass", &s.mass},
                         {"inertia", &s.inertia}});
  return out;
}

void expect_sized(Snapshot& s, std::size_t n, std::size_t kept) {
  for (auto [name, v] : real_arrays(s)) {
    ASSERT_EQ(v->size(), n) << name;
    for (std::size_t i = 0; i < n; ++i)
      ASSERT_EQ((*v)[i], i < kept ? 1.5 + static_cast<double>(i) : 0.0) << name << " at " << i;
  }
  ASSERT_EQ(s.material.size(), n);
  ASSERT_EQ(s.motion.size(), n);
  for (std::size_t i = 0; i < n; ++i) {
    ASSERT_EQ(s.material[i], i < kept ? 7 : 0) << i;
    ASSERT_EQ(s.motion[i], i < kept ? Motion::Fixed : Motion{}) << i;
  }
}

void fill(Snapshot& s) {
  for (auto [name, v] : real_arrays(s))
    for (std::size_t i = 0; i < v->size(); ++i) (*v)[i] = 1.5 + static_cast<double>(i);
  for (auto& m : s.material) m = 7;
  for (auto& m : s.motion) m = Motion::Fixed;
}

TEST(SnapshotResize, EveryArrayGrowsAndShrinksKeepingItsValues) {
  Snapshot s;
  s.resize(1000);
  fill(s);
  const std::size_t large = 200000;  // above the threshold of the threads' resize
  s.resize(large);
  expect_sized(s, large, 1000);
  fill(s);
  s.resize(large + 70000);
  expect_sized(s, large + 70000, large);
  fill(s);
  s.resize(3);
  expect_sized(s, 3, 3);
  EXPECT_EQ(real_arrays(s).size(), static_cast<std::size_t>(Snapshot::kArraysPerParticle) + 8);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
