#pragma once
// Scenes numbered in no spatial order, and what a solver numbering them by place must give
// against the scene's order (core/place_numbered_solver): the tests of numbering by place
// and of renumbering mid-run.
#include "core/place_numbered_solver.hpp"
#include "tridem/scene.hpp"
#include "tridem/solver.hpp"
#include "tridem/standard_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <tuple>
#include <vector>

namespace tridem::test {

/// The scene's free triangles in a random order (its walls, the fixed ones, stay).
inline Scene shuffled(Scene s, unsigned seed = 7) {
  std::vector<TriangleSpec> free;
  for (const TriangleSpec& t : s.triangles)
    if (t.motion == Motion::Free) free.push_back(t);
  std::mt19937_64 random(seed);
  std::shuffle(free.begin(), free.end(), random);
  std::size_t k = 0;
  for (TriangleSpec& t : s.triangles)
    if (t.motion == Motion::Free) t = free[k++];
  return s;
}

inline Snapshot snapshot_of(const Solver& solver) {
  Snapshot snap;
  solver.snapshot(snap, true);
  return snap;
}

/// The contacts by (i, j), and a periodic pair's images by their translation: a solver
/// numbering by place lists them in its own order.
inline std::vector<ContactRecord> by_pair(std::vector<ContactRecord> c) {
  std::stable_sort(c.begin(), c.end(), [](const ContactRecord& x, const ContactRecord& y) {
    return std::tie(x.i, x.j, x.image_dx, x.image_dy) < std::tie(y.i, y.j, y.image_dx, y.image_dy);
  });
  return c;
}

/// The same contacts (the scene's ids, each pair's emitter as i), and forces and states
/// within `tolerance` of the largest value of their kind. A contact's
/// point is placed from its emitter's centroid after the step (core/snapshot_fill.hpp), so
/// that the two emitters of a pair place it up to a step's motion apart: `dt` bounds it.
inline void expect_within_rounding(const Snapshot& a, const Snapshot& b, double tolerance,
                                   double dt) {
  ASSERT_EQ(a.size(), b.size());
  double speed = 0;
  for (std::size_t i = 0; i < a.size(); ++i) speed = std::max(speed, std::hypot(a.vx[i], a.vy[i]));
  const double step_motion = 2 * speed * dt;
  ASSERT_EQ(a.contacts.size(), b.contacts.size());
  double force = 0;
  for (const ContactRecord& c : a.contacts) force = std::max(force, std::hypot(c.fx, c.fy));
  ASSERT_GT(force, 0.0) << "the scene must be in contact";
  const std::vector<ContactRecord> ca = by_pair(a.contacts), cb = by_pair(b.contacts);
  for (std::size_t k = 0; k < ca.size(); ++k) {
    const ContactRecord &p = ca[k], &q = cb[k];
    ASSERT_EQ(p.i, q.i) << "contact " << k;
    ASSERT_EQ(p.j, q.j) << "contact " << k;
    EXPECT_NEAR(p.fx, q.fx, tolerance * force) << "contact " << k;
    EXPECT_NEAR(p.fy, q.fy, tolerance * force) << "contact " << k;
    EXPECT_NEAR(p.nx, q.nx, 1e3 * tolerance) << "contact " << k;
    EXPECT_NEAR(p.ny, q.ny, 1e3 * tolerance) << "contact " << k;
    EXPECT_NEAR(p.px, q.px, step_motion) << "contact " << k;
    EXPECT_NEAR(p.py, q.py, step_motion) << "contact " << k;
    // The image's translation (lengths of the cell: its sign is checked; a zero's sign
    // may differ, a Lees-Edwards shift of 0 computed either way).
    EXPECT_NEAR(p.image_dx, q.image_dx, 1e-12) << "contact " << k;
    EXPECT_NEAR(p.image_dy, q.image_dy, 1e-12) << "contact " << k;
  }
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_NEAR(a.x[i], b.x[i], 1e-12) << "particle " << i;
    ASSERT_NEAR(a.y[i], b.y[i], 1e-12) << "particle " << i;
    ASSERT_NEAR(a.vx[i], b.vx[i], 1e-9) << "particle " << i;
    ASSERT_NEAR(a.omega[i], b.omega[i], 1e-6) << "particle " << i;
    ASSERT_EQ(a.material[i], b.material[i]);
    ASSERT_EQ(a.mass[i], b.mass[i]);
  }
}

inline Scene shuffled_bodies(const Scene& s) {
  std::vector<std::int32_t> bodies(s.bodies.size());
  std::iota(bodies.begin(), bodies.end(), 0);
  std::size_t free = 0;
  while (free < s.bodies.size() && s.bodies[free].motion == Motion::Free) ++free;
  std::mt19937_64 random(11);
  std::shuffle(bodies.begin(), bodies.begin() + static_cast<std::ptrdiff_t>(free), random);
  return reordered_scene(s, body_order(s, std::move(bodies)));
}

/// bonded_pile(n) with its triangles in a random order (walls last), each bond between the
/// same triangles, a below b, the bonds sorted.
inline Scene shuffled_bonded(std::size_t n) {
  const Scene s = bonded_pile(n);
  PlaceOrder order;
  order.triangles.resize(s.triangles.size());
  std::iota(order.triangles.begin(), order.triangles.end(), 0);
  std::mt19937_64 random(13);
  std::shuffle(order.triangles.begin(), order.triangles.end() - 3, random);  // walls last
  Scene out = reordered_scene(s, order);
  for (BondSpec& b : out.bonds)
    if (b.a > b.b) std::swap(b.a, b.b);
  std::sort(out.bonds.begin(), out.bonds.end(), [](const BondSpec& x, const BondSpec& y) {
    return std::tie(x.a, x.b) < std::tie(y.a, y.b);
  });
  return out;
}

}  // namespace tridem::test
