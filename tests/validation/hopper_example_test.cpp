// examples/hopper.toml: the grains settle on the gate before it opens, so the gate's row of
// walls.csv carries their weight before the discharge (the gate once slid away from t = 0
// and its logged force was zero at every step). Checked on the example's own walls and
// gate, with the lowest of its grains (the whole example takes minutes on a busy machine),
// run with its outputs up to just before the gate uncovers the orifice.
#include "tridem/run.hpp"
#include "tridem/scene_io.hpp"
#include "unit/io/io_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

struct Hopper {
  Scene scene;
  std::size_t gate = 0;
  double opens_at = 0;       ///< s: the gate's left end reaches the orifice's left edge
  double highest_grain = 0;  ///< m, over the orifice
};

Hopper hopper_example() {
  Hopper h;
  h.scene = read_scene(std::string(TRIDEM_SOURCE_DIR) + "/examples/hopper.toml");
  const auto& tris = h.scene.triangles;
  const auto gate = std::find_if(tris.begin(), tris.end(), [](const TriangleSpec& t) {
    return t.motion == Motion::Prescribed;
  });
  EXPECT_NE(gate, tris.end()) << "the example's gate is its prescribed triangle";
  h.gate = static_cast<std::size_t>(gate - tris.begin());
  // The orifice's left edge: the innermost vertex at y = 0 of the fixed walls left of x = 0.
  double orifice_left = -INFINITY, gate_left = INFINITY;
  for (const TriangleSpec& t : tris)
    for (const Vec2d& v : t.vertices) {
      if (t.motion == Motion::Fixed && v.y == 0 && v.x < 0)
        orifice_left = std::max(orifice_left, v.x);
      if (t.motion == Motion::Free) h.highest_grain = std::max(h.highest_grain, v.y);
    }
  for (const Vec2d& v : gate->vertices) gate_left = std::min(gate_left, v.x);
  EXPECT_GT(gate->velocity.x, 0) << "the gate slides to the right";
  h.opens_at = (orifice_left - gate_left) / gate->velocity.x;
  return h;
}

TEST(HopperExample, GateOpensAfterEveryGrainCouldHaveLanded) {
  const Hopper h = hopper_example();
  // The highest grain falls to the gate in sqrt(2 y / g); bouncing and settling take as
  // long again at least.
  const double g = std::abs(h.scene.simulation.gravity.y);
  const double fall = std::sqrt(2 * h.highest_grain / g);
  EXPECT_GT(h.opens_at, 1.4 * fall)
      << "gate opens at " << h.opens_at << " s, fall " << fall << " s";
  // And the run goes on long enough after it opens for the grains to flow out.
  const double end =
      static_cast<double>(h.scene.simulation.steps) * describe_scene(h.scene).dt_chosen;
  EXPECT_GT(end, h.opens_at + 0.5);
}

TEST(HopperExample, GateCarriesTheSettledGrainsBeforeItOpens) {
  Hopper h = hopper_example();
  Scene& s = h.scene;
  // The example's walls and gate, and its grains in the lowest 7 cm of their region.
  double lowest = INFINITY;
  for (const TriangleSpec& t : s.triangles)
    if (t.motion == Motion::Free)
      for (const Vec2d& v : t.vertices) lowest = std::min(lowest, v.y);
  std::erase_if(s.triangles, [&](const TriangleSpec& t) {
    return t.motion == Motion::Free &&
           std::min({t.vertices[0].y, t.vertices[1].y, t.vertices[2].y}) > lowest + 0.07;
  });
  const auto grains = std::count_if(s.triangles.begin(), s.triangles.end(),
                                    [](const TriangleSpec& t) { return t.motion == Motion::Free; });
  ASSERT_GT(grains, 40);
  test::TempDir dir;
  s.simulation.backend = Backend::Cpu;
  s.output.dir = dir.path().string();
  s.output.every = 0;
  s.output.energy_every = 500;
  // Stopped short of the opening.
  s.simulation.steps = static_cast<std::int64_t>((h.opens_at - 0.01) / describe_scene(s).dt_chosen);
  RunOptions o;
  o.progress = false;
  o.log = nullptr;
  run_scene(s, o);

  // walls.csv: step,time,id,fx,fy,torque. From the time the grains have landed and
  // settled until the gate opens, the grains press down on it: fy < 0 at every logged
  // step, and at the last one at least the weight of one grain.
  const double settled = h.opens_at - 0.2;
  double last_time = 0, last_fy = 0;
  int rows = 0;
  for (const std::string& line : test::read_lines(dir.path() / "walls.csv")) {
    if (line.empty() || line[0] == 's') continue;
    const std::vector<double> v = test::numbers(line);
    if (static_cast<std::size_t>(v[2]) != h.gate || v[1] < settled) continue;
    ASSERT_LT(v[1], h.opens_at) << "logged after the gate opened";
    EXPECT_LT(v[4], 0) << "no grain on the gate at t = " << v[1] << " s";
    last_time = v[1];
    last_fy = v[4];
    ++rows;
  }
  EXPECT_GE(rows, 10) << "too few logged steps between settling and opening";
  double lightest = INFINITY;
  for (const TriangleSpec& t : s.triangles)
    if (t.motion == Motion::Free)
      lightest = std::min(lightest, s.materials[t.material].density * 0.5 *
                                        std::abs(cross(t.vertices[1] - t.vertices[0],
                                                       t.vertices[2] - t.vertices[0])));
  EXPECT_GT(-last_fy, lightest * std::abs(s.simulation.gravity.y))
      << "at t = " << last_time << " s";
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
