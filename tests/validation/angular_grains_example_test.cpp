// examples/angular_grains.toml: its grains are random convex bodies of the requested
// sides and sizes, and the first steps of the pour run on the serial solver without a
// blow-up, every grain staying in the box.
#include "tridem/scene_io.hpp"
#include "tridem/snapshot.hpp"
#include "tridem/solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

TEST(AngularGrainsExample, GrainsAreBodiesOfTheTableAndStayInTheBox) {
  Scene s = read_scene(std::string(TRIDEM_SOURCE_DIR) + "/examples/angular_grains.toml");
  ASSERT_EQ(s.bodies.size(), 3u + 180u);  // the box's three walls, then the grains
  for (std::size_t b = 3; b < s.bodies.size(); ++b) {
    const BodySpec& body = s.bodies[b];
    EXPECT_TRUE(body.count == 3 || body.count == 4);  // pentagons and hexagons
    double area = 0;
    for (std::size_t k = body.first; k < body.first + body.count; ++k) {
      const auto& v = s.triangles[k].vertices;
      area += 0.5 * cross(v[1] - v[0], v[2] - v[0]);
    }
    const double size = 2 * std::sqrt(area / std::numbers::pi);
    EXPECT_TRUE(std::abs(size - 0.02) < 1e-12 || std::abs(size - 0.028) < 1e-12 ||
                std::abs(size - 0.036) < 1e-12)
        << size;
  }
  s.simulation.backend = Backend::Cpu;
  const auto solver = make_solver(s, SolverConfig{});
  // 0.03 s whatever the automatic step (it grew with the per-body bound): the grains
  // start falling and the lowest land.
  solver->advance(static_cast<std::int64_t>(std::ceil(0.03 / solver->dt())));
  Snapshot snap;
  solver->snapshot(snap, false);
  for (std::size_t i = 3; i < snap.size(); ++i) {
    EXPECT_GT(snap.x[i], 0);
    EXPECT_LT(snap.x[i], 0.6);
    EXPECT_GT(snap.y[i], 0);
    // Free fall for 0.03 s reaches 0.3 m/s; a contact gone wrong would throw it faster.
    EXPECT_LT(std::hypot(snap.vx[i], snap.vy[i]), 1.0);
  }
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
