// validate_scene on scenes built in code: same rules as the reader, messages by particle id.
#include "core/particle_model.hpp"
#include "tridem/error.hpp"
#include "tridem/scene_io.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

Scene valid_scene() {
  Scene s;
  s.simulation.steps = 10;
  Material m;
  m.name = "m";
  m.density = 1000;
  m.penalty = 1e6;
  m.tangential_penalty = 1e5;
  s.materials.push_back(m);
  for (int i = 0; i < 3; ++i) {
    TriangleSpec t;
    const double x = 2.0 * i;
    t.vertices = {Vec2d{x, 0}, Vec2d{x + 1, 0}, Vec2d{x, 1}};
    s.triangles.push_back(t);
  }
  return s;
}

void expect_refused(const std::function<void(Scene&)>& spoil,
                    std::initializer_list<std::string_view> parts) {
  Scene s = valid_scene();
  spoil(s);
  try {
    validate_scene(s);
    ADD_FAILURE() << "scene was accepted";
  } catch (const SceneError& e) {
    const std::string message = e.what();
    for (std::string_view part : parts)
      EXPECT_NE(message.find(part), std::string::npos)
          << "message lacks \"" << part << "\":\n  " << message;
  }
}

TEST(SceneValidate, AcceptsValidSceneAndChangesNothing) {
  Scene s = valid_scene();
  std::swap(s.triangles[1].vertices[1], s.triangles[1].vertices[2]);  // clockwise is fine
  const Scene before = s;
  EXPECT_NO_THROW(validate_scene(s));
  EXPECT_EQ(s.triangles[1].vertices[1].y, before.triangles[1].vertices[1].y);
}

TEST(SceneValidate, RefusesBadTriangles) {
  expect_refused([](Scene& s) { s.triangles[2].material = 1; },
                 {"scene built in code", "particle id 2", "material index 1"});
  expect_refused([](Scene& s) { s.triangles[1].material = -1; }, {"particle id 1"});
  expect_refused([](Scene& s) { s.triangles[1].vertices[2] = {4, 0}; },
                 {"particle id 1", "degenerate"});
  expect_refused([](Scene& s) { s.triangles[0].vertices[0].x = NAN; },
                 {"particle id 0", "not finite"});
  expect_refused([](Scene& s) { s.triangles[0].velocity.y = INFINITY; }, {"particle id 0"});
  expect_refused(
      [](Scene& s) {
        s.triangles[2].motion = Motion::Fixed;
        s.triangles[2].angular_velocity = 1;
      },
      {"particle id 2", "fixed"});
  expect_refused([](Scene& s) { s.triangles.clear(); }, {"no triangles"});
}

/// What validate_scene and build_particle_model say of `s` (empty: accepted).
std::pair<std::string, std::string> refusals(const Scene& s) {
  std::string validated, modelled;
  try {
    validate_scene(s);
  } catch (const SceneError& e) {
    validated = e.what();
  }
  try {
    build_particle_model(s);
  } catch (const SceneError& e) {
    modelled = e.what();
  }
  return {validated, modelled};
}

// The solver's particle model refuses a triangle by the same rule and message as
// validate_scene: a scene built in code and never validated cannot reach a solver with a
// triangle the reader would refuse (the two once had their own checks, and the model
// accepted a fixed triangle with a velocity).
TEST(SceneValidate, ParticleModelRefusesByTheSameRules) {
  const std::vector<std::function<void(Scene&)>> spoils = {
      [](Scene& s) { s.triangles[2].material = 1; },
      [](Scene& s) { s.triangles[1].material = -1; },
      [](Scene& s) {
        s.triangles[1].vertices[2] = {4, 0};
      },
      [](Scene& s) { s.triangles[0].vertices[0].x = NAN; },
      [](Scene& s) { s.triangles[0].velocity.y = INFINITY; },
      [](Scene& s) {
        s.triangles[2].motion = Motion::Fixed;
        s.triangles[2].angular_velocity = 1;
      },
      [](Scene& s) { s.triangles.clear(); },
  };
  for (std::size_t k = 0; k < spoils.size(); ++k) {
    Scene s = valid_scene();
    spoils[k](s);
    const auto [validated, modelled] = refusals(s);
    EXPECT_FALSE(validated.empty()) << "spoil " << k;
    EXPECT_EQ(modelled, validated) << "spoil " << k;
  }
}

// Past 65 536 triangles both checks run on the threads: the refusal still names the
// lowest id at fault, whichever thread finds which.
TEST(SceneValidate, ALargeSceneIsRefusedForItsLowestBadTriangle) {
  Scene s = valid_scene();
  const TriangleSpec good = s.triangles[0];
  s.triangles.assign(200000, good);
  for (std::size_t i = 0; i < s.triangles.size(); ++i)
    for (Vec2d& v : s.triangles[i].vertices) v.x += 2.0 * static_cast<double>(i);
  for (const std::size_t bad : {std::size_t{190000}, std::size_t{123457}, std::size_t{150001}})
    s.triangles[bad].vertices[2] = s.triangles[bad].vertices[1];  // degenerate
  s.triangles[160000].material = 3;
  const auto [validated, modelled] = refusals(s);
  EXPECT_NE(validated.find("particle id 123457: triangle is degenerate"), std::string::npos)
      << validated;
  EXPECT_EQ(modelled, validated);
}

TEST(SceneValidate, RefusesBadMaterials) {
  expect_refused([](Scene& s) { s.materials.clear(); }, {"no material"});
  expect_refused([](Scene& s) { s.materials[0].density = 0; }, {"\"m\"", "density"});
  expect_refused([](Scene& s) { s.materials[0].penalty = -1; }, {"penalty"});
  expect_refused([](Scene& s) { s.materials[0].tangential_penalty = 0; },
                 {"tangential_penalty"});
  expect_refused([](Scene& s) { s.materials[0].damping = 1; }, {"damping"});
  expect_refused([](Scene& s) { s.materials.push_back(s.materials[0]); }, {"duplicate"});
}

TEST(SceneValidate, RefusesBadSettingsAndNamesTheSource) {
  expect_refused(
      [](Scene& s) {
        s.source = "my.toml";
        s.simulation.steps = 0;
      },
      {"my.toml", "steps"});
  expect_refused([](Scene& s) { s.simulation.dt = 0.0; }, {"dt"});
  expect_refused([](Scene& s) { s.simulation.safety = 2; }, {"safety"});
  expect_refused([](Scene& s) { s.simulation.local_damping = -0.5; }, {"local_damping"});
  expect_refused([](Scene& s) { s.output.every = -1; }, {"every"});
  expect_refused([](Scene& s) { s.simulation.max_penetration = 0; }, {"max_penetration"});
  expect_refused([](Scene& s) { s.output.checkpoint_every = -2; }, {"checkpoint_every"});
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
