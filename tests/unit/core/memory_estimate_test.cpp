// `tridem info`'s memory estimate (core/memory_estimate) counts the cohesive bonds: a bonded
// scene costs its bonds' bytes on top of the same triangles unbonded, and a bond's bytes
// cover at least the solver's state of it.
#include "core/memory_estimate.hpp"
#include "physics/cohesive_bond.hpp"
#include "support/scene_builder.hpp"
#include "tridem/run.hpp"
#include "tridem/scene.hpp"

#include <gtest/gtest.h>

namespace tridem {
namespace {

Scene two_bonded_triangles() {
  Scene s;
  s.source = "two bonded triangles";
  s.materials = {test::granite()};
  TriangleSpec a, b;
  a.vertices = {Vec2d{0, 0}, Vec2d{1, 0}, Vec2d{1, 1}};
  b.vertices = {Vec2d{0, 0}, Vec2d{1, 1}, Vec2d{0, 1}};
  s.triangles = {a, b};
  s.bonds = {BondSpec{0, 1, Vec2d{0, 0}, Vec2d{1, 1}}};
  s.simulation.steps = 1;
  return s;
}

TEST(MemoryEstimate, CountsTheBonds) {
  const Scene bonded = two_bonded_triangles();
  Scene loose = bonded;
  loose.bonds.clear();
  const SceneInfo with = describe_scene(bonded), without = describe_scene(loose);
  EXPECT_EQ(with.memory_bytes - without.memory_bytes, cpu_bond_bytes(Precision::Double));
  EXPECT_GT(cpu_bond_bytes(Precision::Double),
            sizeof(physics::BondGeometry<double>) + sizeof(physics::BondForce<double>));
  EXPECT_LT(cpu_bond_bytes(Precision::Float), cpu_bond_bytes(Precision::Double));
}

}  // namespace
}  // namespace tridem
