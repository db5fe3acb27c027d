// GPU ranks (src/mpi/device_choice, mpi_solver.cpp's refusal): which GPU a rank picks from
// its rank on the node, and what a rank without one says. The run itself needs a GPU:
// bench/run_mpi_gpu_on_device.sh.
#include "mpi/device_choice.hpp"
#include "core/particle_model.hpp"
#include "mpi/mpi_solver.hpp"
#include "tridem/scene.hpp"

#include <gtest/gtest.h>

namespace tridem::mpi {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

TEST(MpiDeviceChoice, RanksOfANodeShareItsGpusRoundRobin) {
  // One GPU: every rank on it (the H200 machine's 2 ranks sharing one GPU).
  EXPECT_EQ(device_for_rank(0, 1), 0);
  EXPECT_EQ(device_for_rank(1, 1), 0);
  EXPECT_EQ(device_for_rank(5, 1), 0);
  // As many ranks as GPUs: one each, in order.
  for (int r = 0; r < 8; ++r) EXPECT_EQ(device_for_rank(r, 8), r);
  // More ranks than GPUs: the local rank modulo the count.
  EXPECT_EQ(device_for_rank(2, 2), 0);
  EXPECT_EQ(device_for_rank(3, 2), 1);
  EXPECT_EQ(device_for_rank(7, 4), 3);
}

TEST(MpiDeviceChoice, ARankWithoutAGpuSaysWhichAndWhy) {
  EXPECT_EQ(gpu_rank_refusal("pile.toml", 0, 1, ""), "");
  const std::string m = gpu_rank_refusal("pile.toml", 2, 0, "no CUDA device is present");
  EXPECT_NE(m.find("pile.toml"), std::string::npos) << m;
  EXPECT_NE(m.find("backend = \"cuda\" on MPI ranks needs a GPU"), std::string::npos) << m;
  EXPECT_NE(m.find("rank 2 has none (no CUDA device is present)"), std::string::npos) << m;
  EXPECT_NE(m.find("backend = \"cpu\""), std::string::npos) << m;
}

TEST(MpiRefusal, CudaIsNoLongerRefusedOnRanks) {
  Scene scene;
  scene.source = "pile.toml";
  scene.simulation.backend = Backend::Cuda;
  const ParticleModel model;
  EXPECT_EQ(refusal(scene, model), "");
  // What GPU ranks cannot split either is still refused, with the same message as CPU ranks.
  scene.simulation.method = Method::AllPairs;
  EXPECT_NE(refusal(scene, model).find("all-pairs"), std::string::npos);
}

// backend = "auto" falls back on CPU ranks, which run every scene ranks split: its own
// refusal is the CPU ranks'. GPU ranks decline a periodic cell shorter than one GPU's list
// needs (8 reaches and twice the skin), which CPU ranks run; auto's note says so.
TEST(MpiRefusal, AutoIsRefusedOnlyWhatCpuRanksCannotRun) {
  Scene scene;
  scene.source = "gas.toml";
  scene.simulation.backend = Backend::Auto;
  Material grain;
  grain.name = "g";
  grain.density = 1000;
  grain.penalty = 1e7;
  scene.materials.push_back(grain);
  TriangleSpec t;
  t.vertices = {Vec2d{0.1, 0.1}, Vec2d{0.2, 0.1}, Vec2d{0.15, 0.18}};
  scene.triangles.push_back(t);
  scene.simulation.periodic.x = PeriodicRange{0, 0.6};  // reach 0.057: 8 of it are 0.45
  ParticleModel model = build_particle_model(scene);
  EXPECT_EQ(refusal(scene, model), "");
  EXPECT_EQ(refusal(scene, model, Backend::Cuda), "");
  EXPECT_EQ(gpu_ranks_decline(scene, model), "");
  scene.simulation.periodic.x = PeriodicRange{0, 0.3};  // over 4 reaches, not 8
  model = build_particle_model(scene);
  EXPECT_EQ(refusal(scene, model), "");
  EXPECT_NE(refusal(scene, model, Backend::Cuda).find("too short for backend 'cuda'"),
            std::string::npos);
  const std::string note = gpu_ranks_decline(scene, model);
  EXPECT_NE(note.find("its cell is shorter than"), std::string::npos) << note;
  EXPECT_EQ(note.find("one rank"), std::string::npos) << note;
}

// Bodies on ranks: a servo (its body's load is gathered before the ranks sum it) and a
// moving wall body of several triangles (bodies.csv sums its load from its members' start
// poses) are refused; a fixed wall body of several triangles is not.
TEST(MpiRefusal, WhatBodiesOnCpuRanksCannotDo) {
  Scene scene;
  scene.source = "grains.toml";
  ParticleModel model;
  BodyModel& b = model.bodies;
  b.first = {0, 3, 4};
  b.centroid.resize(2);
  b.motion = {Motion::Fixed, Motion::Free};
  EXPECT_EQ(refusal(scene, model), "");
  b.motion[0] = Motion::Prescribed;
  EXPECT_NE(refusal(scene, model).find("moving wall bodies"), std::string::npos);
  b.motion[0] = Motion::Fixed;
  MotionProgram servo;
  servo.kind = ProgramKind::Servo;
  model.programs.push_back(servo);
  EXPECT_NE(refusal(scene, model).find("servo walls in a scene with bodies"), std::string::npos);
  model.programs.clear();
  // GPU ranks split bodies as CPU ranks do.
  scene.simulation.backend = Backend::Cuda;
  EXPECT_EQ(refusal(scene, model), "");
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem::mpi
