// `tridem info`'s memory estimate (core/memory_estimate) counts the cohesive bonds: a bonded
// scene costs its bonds' bytes on top of the same triangles unbonded, and a bond's bytes
// cover at least the solver's state of it; the GPU's estimate (the CUDA solver's refusal of
// a scene too large for its GPU) counts them too.
#include "core/memory_estimate.hpp"
#include "backends/cuda/cuda_backend.hpp"
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

TEST(MemoryEstimate, CountsTheBondsOnTheGpu) {
  for (Precision p : {Precision::Double, Precision::Float}) {
    const std::size_t n = 1000, pairs = reserved_pairs(n), bonds = 1500;
    EXPECT_EQ(gpu_solver_bytes(n, pairs, p, bonds) - gpu_solver_bytes(n, pairs, p),
              bonds * gpu_bond_bytes(p));
  }
  // At least each bond's columns: geometry, result, damage, the list slots.
  EXPECT_GT(gpu_bond_bytes(Precision::Double), sizeof(physics::BondGeometry<double>) +
                                                   sizeof(physics::BondForce<double>) +
                                                   physics::kBondPoints * sizeof(double) + 16);
  EXPECT_LT(gpu_bond_bytes(Precision::Float), gpu_bond_bytes(Precision::Double));
  // `tridem info` shows it where the build has CUDA (0 without: no GPU estimate at all).
  const Scene bonded = two_bonded_triangles();
  Scene loose = bonded;
  loose.bonds.clear();
  const SceneInfo with = describe_scene(bonded), without = describe_scene(loose);
  if (cuda_solver_bytes(2, Precision::Double) > 0)
    EXPECT_EQ(with.gpu_memory_bytes - without.gpu_memory_bytes, gpu_bond_bytes(Precision::Double));
  else
    EXPECT_EQ(with.gpu_memory_bytes, 0u);
}

}  // namespace
}  // namespace tridem
