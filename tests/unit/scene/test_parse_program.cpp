// The `program = {...}` table of prescribed walls: each kind read into Scene::programs,
// and bad programs refused with the file, line, key and what to do.
#include "scene_refusal.hpp"
#include "tridem/scene_io.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

std::string wall(const std::string& program, const std::string& extra = "") {
  return test::with_triangle("material = \"m\"\nvertices = [[0, 0], [1, 0], [0, 1]]\n"
                             "motion = \"prescribed\"\n" +
                             extra + "program = " + program + "\n");
}

TEST(ParseProgram, ReadsEachKind) {
  Scene s = parse_scene(wall("{ kind = \"rotation\", center = [1, 2], angular_velocity = 3 }"),
                        "ok.toml");
  ASSERT_EQ(s.programs.size(), 1u);
  EXPECT_EQ(s.triangles[0].program, 0);
  EXPECT_EQ(s.programs[0].kind, ProgramKind::Rotation);
  EXPECT_EQ(s.programs[0].center.y, 2);
  EXPECT_EQ(s.programs[0].angular_velocity, 3);

  s = parse_scene(wall("{ kind = \"table\", times = [0, 0.5, 0.6], velocities = [[0, 0], [0, 0], "
                       "[1, 0]], angular_velocities = [0, 0, 2] }"),
                  "ok.toml");
  ASSERT_EQ(s.program_knots.size(), 3u);
  EXPECT_EQ(s.programs[0].knot_count, 3);
  EXPECT_EQ(s.program_knots[2].velocity.x, 1);
  EXPECT_EQ(s.program_knots[2].angular_velocity, 2);

  s = parse_scene(wall("{ kind = \"oscillation\", amplitude = 0.01, frequency = 5, direction = "
                       "[0, 2] }"),
                  "ok.toml");
  EXPECT_EQ(s.programs[0].direction.y, 1);  // made a unit vector
  EXPECT_EQ(s.programs[0].phase, 0);

  s = parse_scene(wall("{ kind = \"servo\", direction = [0, -1], stress = 1e4, length = 0.5, "
                       "gain = 1e-4, max_speed = 0.1 }"),
                  "ok.toml");
  EXPECT_EQ(s.programs[0].kind, ProgramKind::Servo);
  EXPECT_EQ(s.programs[0].target_force, 5000);

  s = parse_scene(wall("{ kind = \"servo\", direction = [0, -1], stress = 1e4, length_between = "
                       "[3, 1], gain = 1e-4, max_speed = 0.1 }"),
                  "ok.toml");
  EXPECT_EQ(s.programs[0].stress, 1e4);
  EXPECT_EQ(s.programs[0].length_walls[0], 3);
  EXPECT_EQ(s.programs[0].length_walls[1], 1);
  EXPECT_EQ(s.programs[0].target_force, 0);  // the model measures the length
}

TEST(ParseProgram, BodyTakesAProgramAsATableOfItsOwn) {
  const std::string text =
      std::string(test::kSceneHead) +
      "[[body]]\nmaterial = \"m\"\npolygon = [[0, 0], [1, 0], [1, 1], [0, 1]]\n"
      "motion = \"prescribed\"\n"
      "[body.program]\nkind = \"rotation\"\ncenter = [0, 0]\n"
      "angular_velocity = 1\n";
  const Scene s = parse_scene(text, "ok.toml");
  ASSERT_EQ(s.bodies.size(), 1u);
  EXPECT_EQ(s.bodies[0].program, 0);
}

// examples/hopper_gate.toml: its gate is the fifth [[triangle]], on a velocity table that
// holds it until 0.5 s and then slides it at 1 m/s (the run itself takes about 15 s).
TEST(ParseProgram, HopperGateExampleOpensByATable) {
  const Scene s = read_scene(std::string(TRIDEM_SOURCE_DIR) + "/examples/hopper_gate.toml");
  ASSERT_EQ(s.programs.size(), 1u);
  EXPECT_EQ(s.triangles[4].program, 0);
  EXPECT_EQ(s.programs[0].kind, ProgramKind::Table);
  ASSERT_EQ(s.program_knots.size(), 3u);
  EXPECT_EQ(s.program_knots[1].time, 0.5);
  EXPECT_EQ(s.program_knots[1].velocity.x, 0);
  EXPECT_EQ(s.program_knots[2].velocity.x, 1);
}

TEST(ParseProgram, RefusesBadPrograms) {
  test::expect_refused(
      test::with_triangle(
          "material = \"m\"\nvertices = [[0, 0], [1, 0], [0, 1]]\n"
          "program = { kind = \"rotation\", center = [0, 0], angular_velocity = 1 }\n"),
      {"bad.toml:", "'program'", "needs motion = \"prescribed\""});
  test::expect_refused(
      wall("{ kind = \"rotation\", center = [0, 0], angular_velocity = 1 }", "velocity = [1, 0]\n"),
      {"'velocity'", "takes its velocity from the program"});
  test::expect_refused(wall("\"rotation\""), {"'program'", "expected a table"});
  test::expect_refused(wall("{ kind = \"spin\" }"), {"'kind'", "\"rotation\", \"table\""});
  test::expect_refused(wall("{ kind = \"rotation\", center = [0, 0] }"),
                       {"its program", "angular_velocity"});
  test::expect_refused(wall("{ kind = \"rotation\", center = [0, 0], angular_velocity = 1, "
                            "speed = 2 }"),
                       {"speed"});
  test::expect_refused(wall("{ kind = \"table\", times = [0, 1], velocities = [[0, 0]] }"),
                       {"'velocities'", "1 velocities for 2 times"});
  test::expect_refused(wall("{ kind = \"table\", times = [0, 1, 1], velocities = [[0, 0], [1, "
                            "0], [2, 0]] }"),
                       {"'times'", "increase strictly"});
  test::expect_refused(wall("{ kind = \"table\", times = [-1], velocities = [[0, 0]] }"),
                       {"'times'", ">= 0"});
  test::expect_refused(wall("{ kind = \"oscillation\", amplitude = 0.01, frequency = 0, "
                            "direction = [1, 0] }"),
                       {"'frequency'", "> 0"});
  test::expect_refused(wall("{ kind = \"oscillation\", amplitude = 0.01, frequency = 1, "
                            "direction = [0, 0] }"),
                       {"'direction'", "must not be [0, 0]"});
  test::expect_refused(wall("{ kind = \"servo\", direction = [0, -1], gain = 1, max_speed = 1 }"),
                       {"give force = F", "stress = S"});
  test::expect_refused(wall("{ kind = \"servo\", direction = [0, -1], force = 10, stress = 3, "
                            "gain = 1, max_speed = 1 }"),
                       {"not both"});
  test::expect_refused(wall("{ kind = \"servo\", direction = [0, -1], stress = 10, gain = 1, "
                            "max_speed = 1 }"),
                       {"'length'"});
  test::expect_refused(wall("{ kind = \"servo\", direction = [0, -1], stress = 10, length = 1, "
                            "length_between = [0, 1], gain = 1, max_speed = 1 }"),
                       {"'length'", "length = L (a fixed length) or length_between", "not both"});
  test::expect_refused(wall("{ kind = \"servo\", direction = [0, -1], force = 10, "
                            "length_between = [0, 1], gain = 1, max_speed = 1 }"),
                       {"'length_between'", "goes with stress, not with force"});
  test::expect_refused(wall("{ kind = \"servo\", direction = [0, -1], stress = 10, "
                            "length_between = [0, 1, 2], gain = 1, max_speed = 1 }"),
                       {"'length_between'", "two wall ids", "got 3 values"});
  test::expect_refused(wall("{ kind = \"servo\", direction = [0, -1], stress = 10, "
                            "length_between = [2, 2], gain = 1, max_speed = 1 }"),
                       {"'length_between'", "names wall 2 twice"});
  test::expect_refused(wall("{ kind = \"servo\", direction = [0, -1], stress = 10, "
                            "length_between = [-1, 2], gain = 1, max_speed = 1 }"),
                       {"'length_between'", "-1 is not a body id"});
  test::expect_refused(wall("{ kind = \"servo\", direction = [0, -1], stress = -10, "
                            "length_between = [0, 2], gain = 1, max_speed = 1 }"),
                       {"'stress'", "reverse direction"});
  test::expect_refused(wall("{ kind = \"servo\", direction = [0, -1], force = 10, gain = 0, "
                            "max_speed = 1 }"),
                       {"'gain'", "> 0"});
  test::expect_refused(wall("{ kind = \"servo\", direction = [0, -1], force = -10, gain = 1, "
                            "max_speed = 1 }"),
                       {"'force'", "reverse direction"});
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
