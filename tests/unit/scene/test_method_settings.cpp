// The settings of the paper's methods: method, contact_test, bbox_prefilter and
// [simulation.decomposition]; how they are read, refused, and checked again when a
// command line or a test changes the method.
#include "scene_refusal.hpp"
#include "support/scene_builder.hpp"
#include "tridem/error.hpp"
#include "tridem/setting_names.hpp"

#include <gtest/gtest.h>

#include <string>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using test::expect_refused;
using test::kGoodTriangle;

/// A valid scene whose [simulation] has `settings` from line 3 on.
std::string scene_with(std::string_view settings) {
  return "[simulation]\nsteps = 5\n" + std::string(settings) +
         "[[material]]\nname = \"m\"\ndensity = 1000\npenalty = 1e6\n" +
         std::string(kGoodTriangle);
}

TEST(SceneMethodSettings, EveryMethodSpellingIsRead) {
  for (const auto& [name, method] : kMethodNames) {
    const Scene s = parse_scene(scene_with("method = \"" + std::string(name) + "\"\n"), "m.toml");
    EXPECT_EQ(s.simulation.method, method) << name;
    EXPECT_EQ(method_name(method), name);
  }
}

TEST(SceneMethodSettings, ContactTestAndPrefilterOfSingleDomain) {
  const Scene s = parse_scene(scene_with("method = \"single-domain\"\n"
                                         "contact_test = \"direct-area\"\n"
                                         "bbox_prefilter = false\n"),
                              "sd.toml");
  EXPECT_EQ(s.simulation.contact_test, ContactTest::DirectArea);
  EXPECT_FALSE(s.simulation.bbox_prefilter);
  // The defaults may be written out with any method.
  const Scene g = parse_scene(scene_with("contact_test = \"exact\"\nbbox_prefilter = true\n"),
                              "g.toml");
  EXPECT_EQ(g.simulation.contact_test, ContactTest::Exact);
  EXPECT_TRUE(g.simulation.bbox_prefilter);
}

TEST(SceneMethodSettings, DecompositionTable) {
  const Scene s = parse_scene(scene_with("method = \"decomposition\"\n"
                                         "[simulation.decomposition]\n"
                                         "layout = \"1d\"\ncapacity = 2\n"),
                              "d.toml");
  EXPECT_EQ(s.simulation.decomposition.layout, DecompositionLayout::Strips);
  EXPECT_EQ(s.simulation.decomposition.capacity, 2);
  const Scene t = parse_scene(scene_with("[simulation.decomposition]\nlayout = \"2d\"\n"
                                         "rows = 2\ncolumns = 0\n"),
                              "d.toml");
  EXPECT_EQ(t.simulation.decomposition.layout, DecompositionLayout::Grid);
  EXPECT_EQ(t.simulation.decomposition.rows, 2);
  EXPECT_EQ(t.simulation.decomposition.columns, 0);
  EXPECT_EQ(t.simulation.decomposition.capacity, 256);
}

TEST(SceneMethodSettings, ContactTestRefusedWithOtherMethods) {
  expect_refused(scene_with("contact_test = \"direct-area\"\n"),
                 {"bad.toml:3:", "key 'contact_test'", "\"single-domain\"", "\"grid\""});
  expect_refused(scene_with("method = \"all-pairs\"\ncontact_test = \"direct-area\"\n"),
                 {"bad.toml:4:", "key 'contact_test'", "\"all-pairs\""});
  expect_refused(scene_with("bbox_prefilter = false\n"),
                 {"bad.toml:3:", "key 'bbox_prefilter'", "\"decomposition\""});
  expect_refused(scene_with("method = \"single-domain\"\ncontact_test = \"vertex\"\n"),
                 {"bad.toml:4:", "key 'contact_test'", "\"exact\", \"direct-area\""});
  expect_refused(scene_with("method = \"single-domain\"\nbbox_prefilter = 1\n"),
                 {"bad.toml:4:", "key 'bbox_prefilter'"});
}

TEST(SceneMethodSettings, DecompositionRefusals) {
  expect_refused(scene_with("decomposition = 3\n"),
                 {"bad.toml:3:", "key 'decomposition'", "[simulation.decomposition]"});
  expect_refused(scene_with("[simulation.decomposition]\nlayout = \"3d\"\n"),
                 {"bad.toml:4:", "[simulation.decomposition]", "key 'layout'", "\"1d\", \"2d\""});
  expect_refused(scene_with("[simulation.decomposition]\nlayout = \"2d\"\nrows = -1\n"),
                 {"bad.toml:5:", "key 'rows'", "[0, "});
  expect_refused(scene_with("[simulation.decomposition]\nlayout = \"2d\"\ncolumns = 1.5\n"),
                 {"bad.toml:5:", "key 'columns'"});
  expect_refused(scene_with("[simulation.decomposition]\ncolumns = 4\n"),
                 {"bad.toml:4:", "key 'columns'", "layout = \"1d\""});
  expect_refused(scene_with("[simulation.decomposition]\ncapacity = 1\n"),
                 {"bad.toml:4:", "key 'capacity'", "[2, "});
  expect_refused(scene_with("[simulation.decomposition]\ncapacity = 3000000000\n"),
                 {"bad.toml:4:", "key 'capacity'"});
  expect_refused(scene_with("[simulation.decomposition]\nlayuot = \"2d\"\n"),
                 {"bad.toml:4:", "[simulation.decomposition]", "unknown key 'layuot'"});
}

/// The message make_solver gives for `scene`, or "" when it accepts it.
std::string solver_refusal(Scene scene, Method method) {
  scene.simulation.backend = Backend::Cpu;
  scene.simulation.method = method;
  try {
    make_solver(scene, SolverConfig{});
  } catch (const SceneError& e) {
    return e.what();
  }
  return {};
}

TEST(SceneMethodSettings, OverridesReplaceTheScenesSettingsAndAreCheckedAgain) {
  Scene s = test::empty_scene();
  s.source = "pile.toml";
  s.triangles.push_back(test::triangle({0, 0}, {1, 0}, {0, 1}));
  s.simulation.method = Method::SingleDomain;
  s.simulation.contact_test = ContactTest::DirectArea;
  SceneOverrides o;
  o.out_dir = "elsewhere";
  o.backend = Backend::OpenMP;
  o.steps = 7;
  o.method = Method::Decomposition;
  o.bbox_prefilter = false;
  const Scene applied = apply_overrides(s, o);
  EXPECT_EQ(applied.output.dir, "elsewhere");
  EXPECT_EQ(applied.simulation.backend, Backend::OpenMP);
  EXPECT_EQ(applied.simulation.steps, 7);
  EXPECT_EQ(applied.simulation.method, Method::Decomposition);
  EXPECT_EQ(applied.simulation.contact_test, ContactTest::DirectArea);
  EXPECT_FALSE(applied.simulation.bbox_prefilter);
  // `--method grid` on a scene set up for the paper's direct-area test: refused by the
  // overrides themselves, naming the scene and the setting.
  SceneOverrides grid;
  grid.method = Method::Grid;
  try {
    apply_overrides(s, grid);
    ADD_FAILURE() << "grid with the direct-area test must be refused";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("pile.toml"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("contact_test = \"direct-area\""), std::string::npos)
        << e.what();
  }
  SceneOverrides no_steps;
  no_steps.steps = 0;
  EXPECT_THROW(apply_overrides(s, no_steps), SceneError);
}

TEST(SceneMethodSettings, SolverChecksTheMethodItIsGiven) {
  // A scene set up for the paper's test, run with another method (as `--method grid`
  // would): refused, not silently run with other physics.
  Scene s = test::empty_scene();
  s.triangles.push_back(test::triangle({0, 0}, {1, 0}, {0, 1}));
  s.simulation.method = Method::SingleDomain;
  s.simulation.contact_test = ContactTest::DirectArea;
  EXPECT_NE(solver_refusal(s, Method::Grid).find("contact_test = \"direct-area\""),
            std::string::npos);
  s.simulation.contact_test = ContactTest::Exact;
  s.simulation.bbox_prefilter = false;
  EXPECT_NE(solver_refusal(s, Method::AllPairs).find("bbox_prefilter = false"),
            std::string::npos);
  EXPECT_EQ(solver_refusal(s, Method::Decomposition), "");
  // And validate_scene, for scenes built in code.
  s.simulation.method = Method::Grid;
  EXPECT_THROW(validate_scene(s), SceneError);
  s.simulation.bbox_prefilter = true;
  s.simulation.decomposition.capacity = 1;
  EXPECT_THROW(validate_scene(s), SceneError);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
