// [[measure]] tables (issue 15): what is read, the defaults, and each refusal with a
// message that names the file, the line, the table and the key.
#include "scene_refusal.hpp"
#include "support/scene_builder.hpp"
#include "tridem/scene_io.hpp"

#include <gtest/gtest.h>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using test::expect_refused;
using test::kGoodTriangle;
using test::kSceneHead;

/// The test head, then `measures` (from line 7), then a triangle.
std::string with_measures(std::string_view output, std::string_view measures) {
  return std::string(kSceneHead) + std::string(measures) + std::string(output) +
         std::string(kGoodTriangle);
}

TEST(SceneMeasure, ReadsEveryKeyAndItsDefaults) {
  const Scene s = parse_scene(with_measures("[output]\nevery = 10\nenergy_every = 4\n",
                                            "[[measure]]\nname = \"core\"\n"
                                            "region = [[0.5, -1], [2, 3.5]]\nevery = 7\n"
                                            "file = \"core_stress.csv\"\n"
                                            "[[measure]]\nname = \"all-of-it_2\"\n"),
                              "good.toml");
  ASSERT_EQ(s.output.measures.size(), 2u);
  const MeasureSpec& core = s.output.measures[0];
  EXPECT_EQ(core.name, "core");
  ASSERT_TRUE(core.region.has_value());
  EXPECT_EQ(core.region->lo.x, 0.5);
  EXPECT_EQ(core.region->lo.y, -1);
  EXPECT_EQ(core.region->hi.x, 2);
  EXPECT_EQ(core.region->hi.y, 3.5);
  EXPECT_DOUBLE_EQ(core.region->area(), 6.75);
  EXPECT_EQ(s.output.measure_every(core), 7);
  EXPECT_EQ(core.file_name(), "core_stress.csv");
  const MeasureSpec& all = s.output.measures[1];
  EXPECT_FALSE(all.region.has_value());
  EXPECT_EQ(s.output.measure_every(all), 4);  // [output] energy_every
  EXPECT_EQ(all.file_name(), "measure_all-of-it_2.csv");
}

TEST(SceneMeasure, EveryDefaultsToTheLogsCadenceAndItsDefault) {
  // energy_every unset: the logs follow [output] every, and so do the measures.
  const Scene s = parse_scene(
      with_measures("[output]\nevery = 25\n", "[[measure]]\nname = \"m\"\n"), "good.toml");
  EXPECT_EQ(s.output.measure_every(s.output.measures.at(0)), 25);
  const Scene none = parse_scene(with_measures("", ""), "good.toml");
  EXPECT_TRUE(none.output.measures.empty());
}

TEST(SceneMeasure, RefusesAnUnknownKey) {
  expect_refused(with_measures("", "[[measure]]\nname = \"m\"\nregoin = [[0, 0], [1, 1]]\n"),
                 {"bad.toml:9:1", "[[measure]] #1", "unknown key 'regoin'"});
}

TEST(SceneMeasure, RefusesAnEmptyOrMalformedRegion) {
  expect_refused(
      with_measures("", "[[measure]]\nname = \"m\"\nregion = [[1, 0], [1, 2]]\n"),
      {"bad.toml:9:", "[[measure]] #1", "'region'", "is empty", "xmin < xmax and ymin < ymax"});
  expect_refused(with_measures("", "[[measure]]\nname = \"m\"\nregion = [[0, 2], [1, 1]]\n"),
                 {"bad.toml:9:", "'region'", "is empty"});
  expect_refused(with_measures("", "[[measure]]\nname = \"m\"\nregion = [[0, 0]]\n"),
                 {"bad.toml:9:", "'region'", "2 corners [[xmin, ymin], [xmax, ymax]]"});
}

TEST(SceneMeasure, RefusesANegativeEvery) {
  expect_refused(with_measures("", "[[measure]]\nname = \"m\"\nevery = -5\n"),
                 {"bad.toml:9:", "[[measure]] #1", "'every'", "must be >= 0", "got -5"});
}

TEST(SceneMeasure, RefusesBadNamesAndFiles) {
  expect_refused(with_measures("", "[[measure]]\nregion = [[0, 0], [1, 1]]\n"),
                 {"bad.toml:7:", "[[measure]] #1", "missing required key 'name'"});
  expect_refused(with_measures("", "[[measure]]\nname = \"a b\"\n"),
                 {"bad.toml:8:", "'name'", "letters, digits"});
  expect_refused(with_measures("", "[[measure]]\nname = \"m\"\nfile = \"../m.csv\"\n"),
                 {"bad.toml:9:", "'file'", "without folders"});
  expect_refused(with_measures("", "[[measure]]\nname = \"m\"\nfile = \"energy.csv\"\n"),
                 {"bad.toml:9:", "'file'", "tridem writes itself"});
  expect_refused(with_measures("", "[[measure]]\nname = \"m\"\n[[measure]]\nname = \"m\"\n"),
                 {"bad.toml:9:", "[[measure]] #2", "name \"m\" is already used by [[measure]] #1"});
  expect_refused(with_measures("", "[[measure]]\nname = \"a\"\nfile = \"measure_b.csv\"\n"
                                   "[[measure]]\nname = \"b\"\n"),
                 {"[[measure]] #2", "file \"measure_b.csv\" is already written by [[measure]] #1"});
  expect_refused(with_measures("", "[measure]\nname = \"m\"\n"),
                 {"bad.toml:7:", "'measure' must be an array of tables, written [[measure]]"});
}

TEST(SceneMeasure, ValidationRefusesTheSameInASceneBuiltInCode) {
  Scene s = test::empty_scene();
  s.triangles.push_back(test::triangle({0, 0}, {1, 0}, {0, 1}));
  MeasureSpec m;
  m.name = "m";
  m.region = MeasureRegion{{0, 0}, {0, 1}};
  s.output.measures.push_back(m);
  try {
    validate_scene(s);
    ADD_FAILURE() << "an empty region was accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("[[measure]] #1 region"), std::string::npos) << e.what();
  }
  s.output.measures[0].region.reset();
  s.output.measures[0].every = -1;
  EXPECT_THROW(validate_scene(s), SceneError);
  s.output.measures[0].every = 0;
  EXPECT_NO_THROW(validate_scene(s));
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
