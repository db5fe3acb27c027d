// The penetration check: two triangles overlapping far deeper than any contact should
// stop the run at the first step, naming both particles and the limit; serial and OpenMP
// report the same pair, and so does the GPU; max_penetration = 1 turns the check off.
#include "support/gpu.hpp"
#include "support/scene_builder.hpp"
#include "tridem/error.hpp"
#include "tridem/solver.hpp"

#include <gtest/gtest.h>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

/// A vertex of particle 1 at (0.3, 0.3), where φ of particle 0 is 0.9.
Scene deep_overlap() {
  Scene s = test::empty_scene(1e3);
  s.triangles.push_back(test::triangle({0, 0}, {1, 0}, {0, 1}));
  s.triangles.push_back(test::triangle({0.3, 0.3}, {1.3, 0.3}, {0.3, 1.3}));
  return s;
}

std::string blow_up_message(Scene s, Backend backend) {
  s.simulation.backend = backend;
  auto solver = make_solver(s, SolverConfig{});
  try {
    solver->advance(1);
  } catch (const RunError& e) {
    EXPECT_EQ(solver->step(), 0) << "the state must stay the last good one";
    return e.what();
  }
  return "";
}

TEST(BlowUp, DeepPenetrationStopsTheRunNamingThePair) {
  const std::string message = blow_up_message(deep_overlap(), Backend::Cpu);
  for (const char* part : {"blow-up at step 1", "particles 0", "and 1", "depth 0.9",
                           "max_penetration = 0.8"})
    EXPECT_NE(message.find(part), std::string::npos) << part << " not in: " << message;
  EXPECT_EQ(blow_up_message(deep_overlap(), Backend::OpenMP), message);
}

TEST(BlowUp, LimitIsTheSceneKeyAndOneTurnsItOff) {
  Scene s = deep_overlap();
  s.simulation.max_penetration = 0.95;
  EXPECT_EQ(blow_up_message(s, Backend::Cpu), "");
  s.simulation.max_penetration = 0.85;
  EXPECT_NE(blow_up_message(s, Backend::Cpu), "");
  s.simulation.max_penetration = 1;
  EXPECT_EQ(blow_up_message(s, Backend::Cpu), "");
}

// The GPU checks every pair in its kernel and reports the same lowest emitter.
TEST(GpuBlowUp, DeepPenetrationGivesTheCpuMessage) {
  TRIDEM_SKIP_WITHOUT_GPU();
  const std::string cpu = blow_up_message(deep_overlap(), Backend::Cpu);
  EXPECT_EQ(blow_up_message(deep_overlap(), Backend::Cuda), cpu);
  Scene s = deep_overlap();
  s.simulation.max_penetration = 0.95;
  EXPECT_EQ(blow_up_message(s, Backend::Cuda), "");
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
