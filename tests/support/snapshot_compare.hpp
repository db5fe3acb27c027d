#pragma once
// Bit-for-bit comparison of two snapshots: what deterministic backends must give.
#include "tridem/snapshot.hpp"

#include <gtest/gtest.h>

namespace tridem::test {

inline void expect_identical(const Snapshot& a, const Snapshot& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a.x[i], b.x[i]) << "particle " << i;
    ASSERT_EQ(a.y[i], b.y[i]) << "particle " << i;
    ASSERT_EQ(a.theta[i], b.theta[i]) << "particle " << i;
    ASSERT_EQ(a.vx[i], b.vx[i]) << "particle " << i;
    ASSERT_EQ(a.vy[i], b.vy[i]) << "particle " << i;
    ASSERT_EQ(a.omega[i], b.omega[i]) << "particle " << i;
    ASSERT_EQ(a.fx[i], b.fx[i]) << "particle " << i;
    ASSERT_EQ(a.torque[i], b.torque[i]) << "particle " << i;
  }
  ASSERT_EQ(a.contacts.size(), b.contacts.size());
}

}  // namespace tridem::test
