// `tridem info`'s memory estimate (core/memory_estimate) counts the cohesive bonds: a bonded
// scene costs its bonds' bytes on top of the same triangles unbonded, and a bond's bytes
// cover at least the solver's state of it; the GPU's estimate (the CUDA solver's refusal of
// a scene too large for its GPU) counts them too. Its pairs are the first list's
// (first_list_pairs), as the CUDA solver sizes its pair slots.
#include "core/memory_estimate.hpp"
#include "backends/cuda/cuda_backend.hpp"
#include "broadphase/candidate_pairs.hpp"
#include "core/particle_model.hpp"
#include "physics/cohesive_bond.hpp"
#include "physics/geometry.hpp"
#include "physics/pair_record.hpp"
#include "support/gpu.hpp"
#include "support/scene_builder.hpp"
#include "tridem/run.hpp"
#include "tridem/scene.hpp"
#include "tridem/solver.hpp"
#include "tridem/standard_scenes.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

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
  if (cuda_solver_bytes(2, 0, Precision::Double) > 0)
    EXPECT_EQ(with.gpu_memory_bytes - without.gpu_memory_bytes, gpu_bond_bytes(Precision::Double));
  else
    EXPECT_EQ(with.gpu_memory_bytes, 0u);
}

// A frame's contact network crosses from the GPU a window of rows at a time, so the
// estimate counts one window's scratch (and each particle's first row), not a row per
// contact: above the window's size it is linear in n with the window as its intercept.
TEST(MemoryEstimate, GpuCountsOneWindowOfAFramesContacts) {
  for (Precision p : {Precision::Double, Precision::Float}) {
    const std::size_t n = 10'000'000;
    ASSERT_GT(reserved_pairs(n), kContactRowsPerCopy);
    const std::size_t one = gpu_solver_bytes(n, 0, p), two = gpu_solver_bytes(2 * n, 0, p);
    const std::size_t per_particle = (two - one) / n;
    EXPECT_EQ(two - one, per_particle * n);
    EXPECT_EQ(gpu_solver_bytes(10 * n, 0, p) - one, 9 * (two - one));
    const std::size_t row = p == Precision::Float ? sizeof(physics::TouchingPair<float>)
                                                  : sizeof(physics::TouchingPair<double>);
    EXPECT_EQ(one - per_particle * n, (16u << 20) + 4 + kContactRowsPerCopy * row);
    // A small scene's window is its possible pairs', not 2^22 rows.
    EXPECT_LT(gpu_solver_bytes(1000, 0, p), std::size_t{20} << 20);
  }
}

/// The pairs of `model` whose boxes widened by `margin` overlap, one free, by brute force.
std::size_t overlapping_boxes(const ParticleModel& model, double margin) {
  std::vector<physics::Aabb<double>> box(model.size());
  for (std::size_t i = 0; i < model.size(); ++i) {
    Vec2d lo = model.centroid[i], hi = model.centroid[i];
    for (const Vec2d& r : model.offsets[i]) {
      const Vec2d v = model.centroid[i] + r;
      lo = {std::min(lo.x, v.x), std::min(lo.y, v.y)};
      hi = {std::max(hi.x, v.x), std::max(hi.y, v.y)};
    }
    box[i] = {{lo.x - margin, lo.y - margin}, {hi.x + margin, hi.y + margin}};
  }
  std::size_t count = 0;
  for (std::size_t i = 0; i < model.size(); ++i)
    for (std::size_t j = i + 1; j < model.size(); ++j)
      if ((model.motion[i] == Motion::Free || model.motion[j] == Motion::Free) &&
          physics::boxes_overlap(box[i], box[j]))
        ++count;
  return count;
}

TEST(MemoryEstimate, FirstListPairsAreTheBoxesThatOverlapWithinTheSkin) {
  for (const double skin : {0.0, 0.05, 0.3}) {
    Scene s = dense_pile(400);
    s.simulation.skin = skin;
    const ParticleModel model = build_particle_model(s);
    const double cell = classify_for_grid(model.longest_edge, model.motion).cell;
    const std::size_t listed = first_list_pairs(s, model);
    EXPECT_EQ(listed, overlapping_boxes(model, skin * cell)) << "skin " << skin;
    EXPECT_GT(listed, model.size()) << "a dense pile touches its neighbours";
  }
}

TEST(MemoryEstimate, GpuPairSlotsAreTheFirstListsNotAFixedRule) {
  // A dense pile and the same grains spread ten times as far apart (the same sizes): the
  // spread ones list next to no pair, and are told so (the fixed rule of ten slots a
  // triangle gave both the same).
  const Scene dense = dense_pile(400);
  Scene spread = dense;
  for (TriangleSpec& t : spread.triangles)
    if (t.motion == Motion::Free) {
      const Vec2d c = (t.vertices[0] + t.vertices[1] + t.vertices[2]) * (1.0 / 3);
      for (Vec2d& v : t.vertices) v = v + c * 9.0;
    }
  const ParticleModel dense_model = build_particle_model(dense);
  const std::size_t n = dense_model.size();
  const std::size_t dense_pairs = first_list_pairs(dense, dense_model);
  const std::size_t spread_pairs = first_list_pairs(spread, build_particle_model(spread));
  EXPECT_LT(spread_pairs, dense_pairs / 4);
  for (Precision p : {Precision::Double, Precision::Float}) {
    EXPECT_EQ(gpu_solver_bytes(n, dense_pairs, p) - gpu_solver_bytes(n, 0, p),
              dense_pairs * gpu_pair_bytes(p));
    if (cuda_solver_bytes(n, 0, p) > 0) {
      EXPECT_EQ(cuda_solver_bytes(n, dense_pairs, p),
                gpu_solver_bytes(n, pair_slots_for(dense_pairs), p));
    }
  }
  const SceneInfo d = describe_scene(dense);
  if (d.gpu_memory_bytes > 0) {
    EXPECT_EQ(d.gpu_memory_bytes, cuda_solver_bytes(n, dense_pairs, Precision::Double));
    EXPECT_LT(describe_scene(spread).gpu_memory_bytes, d.gpu_memory_bytes);
  }
  EXPECT_EQ(d.memory_bytes, cpu_run_bytes(n, dense_pairs, Precision::Double));
  EXPECT_EQ(d.first_list_pairs, dense_pairs);
  EXPECT_EQ(pair_slots_for(dense_pairs), dense_pairs + dense_pairs / 5 + 1024);
}

// On the GPU: the CUDA solver's pair slots after its first build are that list's count and
// a fifth more (not ten a triangle), and first_list_pairs, which `tridem info` sizes them
// by, is an upper bound of the list (the contact test drops some candidates) near it.
TEST(GpuMemory, PairSlotsAreTheFirstListsCountAndAFifth) {
  TRIDEM_SKIP_WITHOUT_GPU();
  for (Precision p : {Precision::Double, Precision::Float}) {
    Scene s = dense_pile(3000);
    s.simulation.backend = Backend::Cuda;
    s.simulation.precision = p;
    auto solver = make_solver(s, {});
    solver->advance(1);
    long long builds = 0, steps = 0;
    std::size_t listed = 0, room = 0;
    ASSERT_EQ(std::sscanf(solver->statistics().c_str(),
                          "pair list built %lld times in %lld steps; %zu pairs (room for %zu)",
                          &builds, &steps, &listed, &room),
              4)
        << solver->statistics();
    ASSERT_EQ(builds, 1);
    EXPECT_EQ(room, pair_slots_for(listed));
    EXPECT_LT(room, reserved_pairs(s.triangles.size()));
    const std::size_t estimate = first_list_pairs(s, build_particle_model(s));
    EXPECT_GE(estimate, listed);
    EXPECT_LE(estimate, 2 * listed);
  }
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
