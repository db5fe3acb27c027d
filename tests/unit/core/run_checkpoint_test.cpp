// The run loop's side of checkpoints: restarted runs continue the output files exactly
// (rows written after the checkpoint by a run that died are replaced, not duplicated), an
// interruption and a blow-up leave a loadable checkpoint and final.csv.
#include "core/place_numbered_solver.hpp"
#include "core/solver_factory.hpp"
#include "support/body_scenes.hpp"
#include "support/place_order_scenes.hpp"
#include "support/scene_builder.hpp"
#include "tridem/checkpoint.hpp"
#include "tridem/error.hpp"
#include "tridem/run.hpp"
#include "tridem/scene_io.hpp"
#include "unit/io/io_test_support.hpp"

#include <gtest/gtest.h>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

namespace fs = std::filesystem;

Scene pile(const fs::path& dir) {
  Scene s = test::jostling_pile(6, 4);
  s.simulation.steps = 300;
  s.simulation.backend = Backend::Cpu;
  s.output.dir = dir.string();
  s.output.every = 50;
  s.output.checkpoint_every = 100;
  MeasureSpec all;  // a [[measure]]'s file is cut back and continued like the logs
  all.name = "all";
  s.output.measures.push_back(all);
  return s;
}

RunSummary run(const Scene& s, std::optional<std::int64_t> steps = std::nullopt,
               std::optional<fs::path> restart = std::nullopt,
               ParticleOrder order = ParticleOrder::Auto) {
  RunOptions o;
  o.progress = false;
  o.log = nullptr;
  o.particle_order = order;
  if (restart) o.restart = restart->string();
  SceneOverrides overrides;  // as `tridem run --steps` would
  overrides.steps = steps;
  return run_scene(apply_overrides(s, overrides), o);
}

void expect_same_outputs(const fs::path& a, const fs::path& b) {
  for (const char* f :
       {"energy.csv", "walls.csv", "final.csv", "tridem.pvd", "contacts.pvd",
        "frames/frame_000000300.vtu", "contacts/contacts_000000250.csv", "measure_all.csv"})
    EXPECT_EQ(test::read_file(a / f), test::read_file(b / f)) << f;
}

TEST(RunCheckpoint, RestartContinuesTheOutputsExactly) {
  test::TempDir dir;
  const Scene straight = pile(dir.path() / "straight");
  run(straight);
  EXPECT_EQ(read_checkpoint(dir.path() / "straight" / "checkpoint.ckpt").state.step, 300);

  // A run that dies at step 250, after its checkpoint at 200 was written.
  const Scene broken = pile(dir.path() / "broken");
  run(broken, 200);
  const fs::path saved = dir.path() / "at200.ckpt";
  fs::copy_file(dir.path() / "broken" / "checkpoint.ckpt", saved);
  run(broken, 250, saved);
  ASSERT_TRUE(fs::exists(dir.path() / "broken" / "frames" / "frame_000000250.vtu"));
  ASSERT_EQ(test::read_lines(dir.path() / "broken" / "measure_all.csv").size(), 1u + 5u)
      << "rows at 50 ... 250, the 250 one to be replaced";

  const RunSummary s = run(broken, std::nullopt, saved);
  EXPECT_EQ(s.steps, 100);
  EXPECT_EQ(s.last_step, 300);
  expect_same_outputs(dir.path() / "straight", dir.path() / "broken");
}

// A run whose solver numbers the particles by place (core/place_numbered_solver) writes
// its checkpoints in the scene's ids; restarted in the same order, it continues the
// outputs exactly.
TEST(RunCheckpoint, RestartOfARunNumberedByPlaceContinuesTheOutputsExactly) {
  test::TempDir dir;
  const ParticleOrder place = ParticleOrder::Place;
  const Scene straight = pile(dir.path() / "straight");
  run(straight, std::nullopt, std::nullopt, place);
  const Scene broken = pile(dir.path() / "broken");
  run(broken, 200, std::nullopt, place);
  const fs::path saved = dir.path() / "at200.ckpt";
  fs::copy_file(dir.path() / "broken" / "checkpoint.ckpt", saved);
  EXPECT_GT(read_checkpoint(saved).state.pairs(), 0u) << "the grains touch at the restart";
  run(broken, std::nullopt, saved, place);
  expect_same_outputs(dir.path() / "straight", dir.path() / "broken");
}

// A run whose solver numbers its particles by place again mid-run (a look every 50 steps,
// at a small pile's spread: tests/unit/core/renumbering_solver_test.cpp) checkpoints the
// order it has; restarted from a checkpoint after the renumbering, it continues the
// outputs exactly.
TEST(RunCheckpoint, RestartOfARunRenumberedMidRunContinuesTheOutputsExactly) {
  test::TempDir dir;
  auto mixed = [&](const char* name) {
    Scene s = test::shuffled(test::jostling_pile(80, 10));
    s.simulation.steps = 300;
    s.simulation.backend = Backend::Cpu;
    s.output.dir = (dir.path() / name).string();
    s.output.every = 50;
    s.output.checkpoint_every = 100;
    return s;
  };
  auto run_renumbering = [](const Scene& s, std::optional<std::int64_t> steps,
                            std::optional<fs::path> restart) {
    RunOptions o;
    o.progress = false;
    o.log = nullptr;
    if (restart) o.restart = restart->string();
    o.make_solver = [](const Scene& scene, const ParticleModel& model, const TimeStep& ts,
                       const SolverConfig& config) {
      return make_renumbering_solver(scene, model, scene_order(model),
                                     scene_order_maker(ts, config), 50, 1.8);
    };
    SceneOverrides overrides;
    overrides.steps = steps;
    return run_scene(apply_overrides(s, overrides), o);
  };
  const RunSummary straight = run_renumbering(mixed("straight"), std::nullopt, std::nullopt);
  EXPECT_NE(straight.solver.find("numbered by place"), std::string::npos) << straight.solver;
  const Scene broken = mixed("broken");
  run_renumbering(broken, 200, std::nullopt);
  const fs::path saved = dir.path() / "at200.ckpt";
  fs::copy_file(dir.path() / "broken" / "checkpoint.ckpt", saved);
  EXPECT_EQ(read_checkpoint(saved).state.particle_order.size(), broken.triangles.size())
      << "the checkpoint carries the order";
  run_renumbering(broken, std::nullopt, saved);
  for (const char* f :
       {"energy.csv", "final.csv", "frames/frame_000000300.vtu", "contacts/contacts_000000250.csv"})
    EXPECT_EQ(test::read_file(dir.path() / "straight" / f),
              test::read_file(dir.path() / "broken" / f))
        << f;
}

// A scene of bodies of several triangles (issue 13) through run_scene, as `tridem run
// --restart` runs it: the restarted run's outputs equal the straight run's.
TEST(RunCheckpoint, RestartOfABodySceneContinuesTheOutputsExactly) {
  test::TempDir dir;
  auto bodies = [&](const char* name) {
    Scene s = test::colliding_bodies();
    s.simulation.steps = 3000;
    s.simulation.backend = Backend::Cpu;
    s.output.dir = (dir.path() / name).string();
    s.output.every = 500;
    s.output.checkpoint_every = 1000;
    return s;
  };
  run(bodies("straight"));
  const Checkpoint end = read_checkpoint(dir.path() / "straight" / "checkpoint.ckpt");
  EXPECT_EQ(end.state.step, 3000);
  EXPECT_EQ(end.state.bodies(), 5u);
  const Scene broken = bodies("broken");
  run(broken, 2000);
  const fs::path saved = dir.path() / "at2000.ckpt";
  fs::copy_file(dir.path() / "broken" / "checkpoint.ckpt", saved);
  EXPECT_GT(read_checkpoint(saved).state.pairs(), 0u) << "the bodies touch at the restart";
  const RunSummary s = run(broken, std::nullopt, saved);
  EXPECT_EQ(s.steps, 1000);
  EXPECT_EQ(s.last_step, 3000);
  for (const char* f : {"energy.csv", "final.csv", "tridem.pvd", "frames/frame_000003000.vtu"})
    EXPECT_EQ(test::read_file(dir.path() / "straight" / f),
              test::read_file(dir.path() / "broken" / f))
        << f;
  EXPECT_EQ(read_checkpoint(dir.path() / "broken" / "checkpoint.ckpt").state.body_x,
            end.state.body_x);
}

TEST(RunCheckpoint, InterruptionWritesCheckpointAndFinal) {
  test::TempDir dir;
  const Scene s = pile(dir.path());
  std::atomic<int> interrupt{15};
  RunOptions o;
  o.progress = false;
  o.log = nullptr;
  o.interrupt = &interrupt;
  const RunSummary summary = run_scene(s, o);
  EXPECT_EQ(summary.interrupted_by, 15);
  EXPECT_EQ(summary.checkpoint, (dir.path() / "checkpoint.ckpt").string());
  EXPECT_EQ(read_checkpoint(summary.checkpoint).state.step, summary.last_step);
  EXPECT_TRUE(fs::exists(dir.path() / "final.csv"));
  // and the run can go on from there to the end
  EXPECT_EQ(run(s, std::nullopt, summary.checkpoint).last_step, 300);
}

TEST(RunCheckpoint, BlowUpKeepsTheLastGoodState) {
  test::TempDir dir;
  Scene s = test::empty_scene(1e3);
  s.triangles.push_back(test::triangle({0, 0}, {1, 0}, {0, 1}));
  s.triangles.push_back(test::triangle({0.3, 0.3}, {1.3, 0.3}, {0.3, 1.3}));
  s.simulation.steps = 10;
  s.output.dir = dir.path().string();
  try {
    run(s);
    ADD_FAILURE() << "no blow-up";
  } catch (const RunError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("last_good.ckpt"), std::string::npos) << message;
    EXPECT_NE(message.find("final.csv"), std::string::npos) << message;
  }
  const Checkpoint good = read_checkpoint(dir.path() / "last_good.ckpt");
  EXPECT_EQ(good.state.step, 0);
  EXPECT_DOUBLE_EQ(good.state.x[1], 0.3 + 1.0 / 3);  // centroid of the untouched particle
  EXPECT_EQ(test::read_lines(dir.path() / "final.csv").size(), 3u);
}

TEST(RunCheckpoint, RestartPastTheEndIsRefused) {
  test::TempDir dir;
  const Scene s = pile(dir.path());
  run(s, 200);
  EXPECT_THROW(run(s, 100, dir.path() / "checkpoint.ckpt"), RunError);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
