#pragma once
// Bit-for-bit comparison of two snapshots: what deterministic backends must give. Every
// field counts (step, time, each per-particle array, each contact record field by field),
// compared by bit pattern, so that -0.0 differs from +0.0 and a NaN equals only itself.
#include "tridem/snapshot.hpp"

#include <bit>
#include <cstdint>
#include <gtest/gtest.h>
#include <ostream>
#include <string>
#include <vector>

namespace tridem {

/// How GoogleTest prints a contact record (found by argument-dependent lookup).
inline void PrintTo(const ContactRecord& c, std::ostream* os) {
  *os << "(" << c.i << ", " << c.j << ") force (" << ::testing::PrintToString(c.fx) << ", "
      << ::testing::PrintToString(c.fy) << ") at (" << ::testing::PrintToString(c.px) << ", "
      << ::testing::PrintToString(c.py) << ")";
}

}  // namespace tridem

namespace tridem::test {

inline bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}
template <class T>
bool same_bits(T a, T b) {
  return a == b;
}

/// The first difference of one per-particle array, as a test failure; false if any.
template <class T>
bool expect_same_array(const char* name, const std::vector<T>& a, const std::vector<T>& b) {
  if (a.size() != b.size()) {
    ADD_FAILURE() << name << ": " << a.size() << " entries against " << b.size();
    return false;
  }
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!same_bits(a[i], b[i])) {
      ADD_FAILURE() << name << " of particle " << i << " differs: " << ::testing::PrintToString(a[i])
                    << " against " << ::testing::PrintToString(b[i]);
      return false;
    }
  return true;
}

inline void expect_identical(const Snapshot& a, const Snapshot& b) {
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a.step, b.step);
  EXPECT_TRUE(same_bits(a.time, b.time)) << "time " << a.time << " against " << b.time;
  struct Field {
    const char* name;
    std::vector<double> Snapshot::*values;
  };
  static constexpr Field kFields[] = {
      {"x", &Snapshot::x},         {"y", &Snapshot::y},   {"theta", &Snapshot::theta},
      {"vx", &Snapshot::vx},       {"vy", &Snapshot::vy}, {"omega", &Snapshot::omega},
      {"fx", &Snapshot::fx},       {"fy", &Snapshot::fy}, {"torque", &Snapshot::torque},
      {"x1", &Snapshot::x1},       {"y1", &Snapshot::y1}, {"x2", &Snapshot::x2},
      {"y2", &Snapshot::y2},       {"x3", &Snapshot::x3}, {"y3", &Snapshot::y3},
      {"mass", &Snapshot::mass},   {"inertia", &Snapshot::inertia}};
  for (const Field& f : kFields) expect_same_array(f.name, a.*f.values, b.*f.values);
  expect_same_array("material", a.material, b.material);
  expect_same_array("motion", a.motion, b.motion);

  EXPECT_EQ(a.contact_precision, b.contact_precision) << "how the contacts CSV prints them";
  ASSERT_EQ(a.contacts.size(), b.contacts.size()) << "contact records";
  for (std::size_t k = 0; k < a.contacts.size(); ++k) {
    const ContactRecord &p = a.contacts[k], &q = b.contacts[k];
    const bool same = p.i == q.i && p.j == q.j && same_bits(p.fx, q.fx) && same_bits(p.fy, q.fy) &&
                      same_bits(p.px, q.px) && same_bits(p.py, q.py) && same_bits(p.nx, q.nx) &&
                      same_bits(p.ny, q.ny) && p.sliding == q.sliding &&
                      same_bits(p.depth, q.depth);
    if (!same) {
      ADD_FAILURE() << "contact record " << k << " differs: " << ::testing::PrintToString(p)
                    << " against " << ::testing::PrintToString(q);
      return;
    }
  }
}

}  // namespace tridem::test
