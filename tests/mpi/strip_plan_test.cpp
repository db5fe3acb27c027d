// The MPI ranks' plan on its own (src/mpi/strip_plan): each free particle has one owner,
// every rank holds every particle that can touch one of its own before a replan, the walls
// and the cell grid's setter; the strips run across the longer side and balance contacts.
#include "mpi/strip_plan.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <random>

namespace tridem::mpi {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

StripInput cloud(std::size_t n, double width, double height, int ranks, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> ux(0, width), uy(0, height), ur(0.005, 0.01);
  StripInput in;
  for (std::size_t i = 0; i < n; ++i) {
    in.x.push_back(ux(rng));
    in.y.push_back(uy(rng));
    in.motion.push_back(i % 17 == 0 ? Motion::Fixed : Motion::Free);
    in.radius.push_back(ur(rng));
    // Walls longer than every grain: never binned, they emit nothing (emitter_rule.hpp).
    in.longest_edge.push_back(in.motion.back() == Motion::Free ? in.radius.back() * 1.7 : 1.0);
    in.contacts.push_back(static_cast<std::int32_t>(i % 5));
  }
  in.ranks = ranks;
  in.skin = 0.01;
  return in;
}

bool holds(const StripPlan& p, int r, std::int32_t i) {
  const auto& h = p.held[static_cast<std::size_t>(r)];
  return std::binary_search(h.begin(), h.end(), i);
}

TEST(MpiStripPlan, EveryParticleIsOwnedOnceAndRanksHoldWhatCanTouchTheirOwn) {
  for (int ranks : {1, 2, 3, 4, 7}) {
    const StripInput in = cloud(400, 1.0, 0.3, ranks, 11u + static_cast<unsigned>(ranks));
    const StripPlan p = plan_strips(in);
    ASSERT_EQ(p.axis, 0);
    double r_max = 0;  // of the grains (these walls are large: they are not owned)
    for (std::size_t i = 0; i < in.x.size(); ++i)
      if (in.motion[i] == Motion::Free) r_max = std::max(r_max, in.radius[i]);
    EXPECT_DOUBLE_EQ(p.margin, 2 * r_max + in.skin);
    for (std::size_t i = 0; i < in.x.size(); ++i) {
      const auto id = static_cast<std::int32_t>(i);
      if (in.motion[i] != Motion::Free) {
        EXPECT_EQ(p.owner[i], -1);
        for (int r = 0; r < ranks; ++r) EXPECT_TRUE(holds(p, r, id)) << "wall " << i;
        continue;
      }
      ASSERT_GE(p.owner[i], 0);
      ASSERT_LT(p.owner[i], ranks);
      EXPECT_TRUE(holds(p, p.owner[i], id));
    }
    for (int r = 0; r < ranks; ++r) {
      const auto& h = p.held[static_cast<std::size_t>(r)];
      EXPECT_TRUE(std::is_sorted(h.begin(), h.end()));
      EXPECT_TRUE(holds(p, r, p.cell_setter));
    }
    // Two grains that can touch once each has moved half the skin: centroids within
    // R_i + R_j + skin. Whoever owns one holds the other.
    for (std::size_t i = 0; i < in.x.size(); ++i)
      for (std::size_t j = 0; j < in.x.size(); ++j) {
        if (in.motion[i] != Motion::Free || in.motion[j] != Motion::Free) continue;
        const double d = std::hypot(in.x[i] - in.x[j], in.y[i] - in.y[j]);
        if (d > in.radius[i] + in.radius[j] + in.skin) continue;
        EXPECT_TRUE(holds(p, p.owner[i], static_cast<std::int32_t>(j)))
            << ranks << " ranks: " << j << " near " << i << " of rank " << p.owner[i];
      }
  }
}

TEST(MpiStripPlan, StripsRunAcrossTheLongerSideAndTheCellSetterIsTheLongestEdge) {
  StripInput in = cloud(200, 0.2, 1.0, 3, 5u);
  in.longest_edge[42] = 0.05;
  const StripPlan p = plan_strips(in);
  EXPECT_EQ(p.axis, 1);
  EXPECT_EQ(p.cell_setter, 42);
  // Strips are ordered along y: rank r's own particles lie below rank r+1's.
  for (int r = 0; r + 1 < 3; ++r)
    EXPECT_LE(p.hi[static_cast<std::size_t>(r)][1], p.lo[static_cast<std::size_t>(r + 1)][1]);
}

TEST(MpiStripPlan, AWallAsSmallAsAGrainIsOwnedLikeOneAndHeldEverywhere) {
  // It emits its pairs with higher ids: its row must be on one rank, with every grain
  // that can reach it.
  StripInput in = cloud(300, 1.0, 0.2, 3, 21u);
  in.motion[150] = Motion::Fixed;
  in.longest_edge[150] = 0.01;
  const StripPlan p = plan_strips(in);
  const int owner = p.owner[150];
  ASSERT_GE(owner, 0);
  for (int r = 0; r < 3; ++r) EXPECT_TRUE(holds(p, r, 150));
  for (std::size_t j = 0; j < in.x.size(); ++j) {
    if (in.motion[j] != Motion::Free) continue;
    const double d = std::hypot(in.x[j] - in.x[150], in.y[j] - in.y[150]);
    if (d <= in.radius[j] + in.radius[150] + in.skin) {
      EXPECT_TRUE(holds(p, owner, static_cast<std::int32_t>(j))) << j;
    }
  }
}

TEST(MpiStripPlan, BordersBalanceContactsNotParticles) {
  // Uniform in x, but the grains of the left quarter carry 20 contacts each: the left
  // rank owns far fewer grains, and the two ranks' weights (1 + contacts) are close.
  StripInput in = cloud(400, 1.0, 0.1, 2, 9u);
  for (std::size_t i = 0; i < in.x.size(); ++i) in.contacts[i] = in.x[i] < 0.25 ? 20 : 0;
  const StripPlan p = plan_strips(in);
  double weight[2] = {0, 0};
  int count[2] = {0, 0};
  for (std::size_t i = 0; i < in.x.size(); ++i) {
    if (p.owner[i] < 0) continue;
    weight[p.owner[i]] += 1 + in.contacts[i];
    ++count[p.owner[i]];
  }
  EXPECT_LT(count[0], count[1] / 3);
  EXPECT_NEAR(weight[0], weight[1], 2 * 21.0);
  EXPECT_LT(p.hi[0][0], 0.25);
}

// In a periodic cell the strips form a ring along the axis: two grains that can touch
// through the boundary (their nearest images within R_i + R_j + skin) are held by each
// other's owner, and the plan holds no more than a margin past each strip's ends either way.
TEST(MpiStripPlan, AlongAPeriodicAxisTheStripsFormARing) {
  for (int ranks : {2, 3, 5}) {
    StripInput in = cloud(400, 1.0, 0.3, ranks, 21u + static_cast<unsigned>(ranks));
    in.periodic[0] = true;
    in.period[0] = 1.0;
    const StripPlan p = plan_strips(in);
    ASSERT_EQ(p.axis, 0);
    std::size_t through = 0;
    for (std::size_t i = 0; i < in.x.size(); ++i)
      for (std::size_t j = 0; j < in.x.size(); ++j) {
        if (in.motion[i] != Motion::Free || in.motion[j] != Motion::Free) continue;
        const double dx = std::remainder(in.x[i] - in.x[j], 1.0);
        if (std::hypot(dx, in.y[i] - in.y[j]) > in.radius[i] + in.radius[j] + in.skin) continue;
        through += std::abs(in.x[i] - in.x[j]) > 0.5;
        EXPECT_TRUE(holds(p, p.owner[i], static_cast<std::int32_t>(j)))
            << ranks << " ranks: " << j << " near " << i << " through the boundary";
      }
    EXPECT_GT(through, 0u) << "the cloud has pairs through the boundary";
    // Without the ring the first and last strips do not hold each other's grains there.
    in.periodic[0] = false;
    const StripPlan open = plan_strips(in);
    std::size_t fewer = 0;
    for (int r = 0; r < ranks; ++r)
      fewer += p.held[static_cast<std::size_t>(r)].size() -
               open.held[static_cast<std::size_t>(r)].size();
    EXPECT_GT(fewer, 0u);
  }
}

// On a square extent 4 and 6 ranks cut a grid (2 x 2, 3 x 2 or 2 x 3: shorter borders than
// strips), a wide one and a prime count cut strips. In a grid too every particle has one
// owner and the owner of a grain holds every grain that can touch it, through a periodic
// boundary as well.
TEST(MpiStripPlan, ASquareExtentIsCutIntoAGrid) {
  EXPECT_FALSE(plan_strips(cloud(300, 1.0, 0.3, 4, 3u)).grid());
  EXPECT_FALSE(plan_strips(cloud(300, 1.0, 1.0, 5, 3u)).grid());
  for (bool periodic : {false, true})
    for (int ranks : {4, 6, 9}) {
      StripInput in = cloud(600, 1.0, 1.0, ranks, 31u + static_cast<unsigned>(ranks));
      in.periodic[0] = in.periodic[1] = periodic;
      in.period[0] = in.period[1] = 1.0;
      const StripPlan p = plan_strips(in);
      ASSERT_TRUE(p.grid()) << ranks;
      EXPECT_EQ(p.cuts[0] * p.cuts[1], ranks);
      std::vector<int> owned(static_cast<std::size_t>(ranks), 0);
      for (std::size_t i = 0; i < in.x.size(); ++i)
        if (in.motion[i] == Motion::Free) ++owned[static_cast<std::size_t>(p.owner[i])];
      for (int r = 0; r < ranks; ++r)
        EXPECT_GT(owned[static_cast<std::size_t>(r)], 600 / ranks / 2);
      auto apart = [&](double d) { return periodic ? std::remainder(d, 1.0) : d; };
      for (std::size_t i = 0; i < in.x.size(); ++i)
        for (std::size_t j = 0; j < in.x.size(); ++j) {
          if (in.motion[i] != Motion::Free || in.motion[j] != Motion::Free) continue;
          const double d = std::hypot(apart(in.x[i] - in.x[j]), apart(in.y[i] - in.y[j]));
          if (d > in.radius[i] + in.radius[j] + in.skin) continue;
          EXPECT_TRUE(holds(p, p.owner[i], static_cast<std::int32_t>(j)))
              << ranks << " ranks: " << j << " near " << i;
        }
    }
}

// Under Lees-Edwards shear the images across the y boundary slide along x: the strips are
// cut along y, each running the whole period in x, whatever the extent's shape.
TEST(MpiStripPlan, UnderShearTheStripsAreCutAlongY) {
  StripInput in = cloud(200, 1.0, 0.3, 3, 5u);
  in.periodic[0] = in.periodic[1] = true;
  in.period[0] = 1.0;
  in.period[1] = 0.3;
  EXPECT_EQ(plan_strips(in).axis, 0);
  in.sheared = true;
  EXPECT_EQ(plan_strips(in).axis, 1);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem::mpi
