// Refused scenes, one rule per test. Each checks that the message names the file, the
// line:column (or the particle id) and the key, so a user can find and fix the mistake.
#include "scene_refusal.hpp"

#include <gtest/gtest.h>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using test::expect_refused;
using test::kGoodTriangle;
using test::kSceneHead;
using test::with_triangle;

std::string head_with(std::string_view block) {
  return std::string(kSceneHead) + std::string(block);
}

TEST(SceneRefusals, TomlSyntaxError) {
  expect_refused("[simulation]\nsteps = = 5\n", {"bad.toml:2:", "TOML syntax error"});
  expect_refused("[simulation\nsteps = 5\n", {"bad.toml:1:", "TOML syntax error"});
}

TEST(SceneRefusals, UnknownKeyInEveryTable) {
  expect_refused("[simulation]\nsteps = 5\nstepz = 3\n",
                 {"bad.toml:3:1", "[simulation]", "unknown key 'stepz'"});
  expect_refused(head_with("[output]\nevry = 3\n") + std::string(kGoodTriangle),
                 {"bad.toml:8:1", "[output]", "unknown key 'evry'"});
  expect_refused(head_with("densty = 5\n") + std::string(kGoodTriangle),
                 {"bad.toml:7:1", "[[material]] #1", "unknown key 'densty'"});
  expect_refused(with_triangle("material = \"m\"\nvertices = [[0, 0], [1, 0], [0, 1]]\n"
                               "velocty = [1, 0]\n"),
                 {"bad.toml:10:1", "[[triangle]] #1 (particle id 0)", "unknown key 'velocty'"});
  expect_refused(head_with("[[generate]]\nkind = \"lattice\"\nmaterial = \"m\"\n"
                           "region = [[0, 0], [5, 5]]\nsize = 1\nspacing = 2\n"),
                 {"bad.toml:12:1", "[[generate]] #1", "unknown key 'spacing'"});
}

TEST(SceneRefusals, UnknownTopLevelTable) {
  expect_refused(head_with("[outptu]\ndir = \"x\"\n") + std::string(kGoodTriangle),
                 {"bad.toml:7:", "unknown top-level table or key 'outptu'"});
  expect_refused("title = 3\n" + head_with(kGoodTriangle), {"bad.toml:1:1", "'title'"});
}

TEST(SceneRefusals, SingleBracketMaterialTable) {
  expect_refused("[simulation]\nsteps = 5\n[material]\nname = \"m\"\n",
                 {"bad.toml:3:", "'material' must be an array of tables, written [[material]]"});
}

TEST(SceneRefusals, MissingRequiredKeys) {
  expect_refused("[simulation]\ndt = 1e-3\n", {"bad.toml:1:1", "[simulation]",
                                                "missing required key 'steps'"});
  expect_refused("[[material]]\nname = \"m\"\ndensity = 1\npenalty = 1\n",
                 {"bad.toml", "missing required table [simulation]"});
  expect_refused(head_with("[[material]]\nname = \"n\"\npenalty = 1e6\n") +
                     std::string(kGoodTriangle),
                 {"bad.toml:7:1", "[[material]] #2", "missing required key 'density'"});
  expect_refused(with_triangle("material = \"m\"\n"),
                 {"bad.toml:7:1", "particle id 0", "missing required key 'vertices'"});
  expect_refused(with_triangle("vertices = [[0, 0], [1, 0], [0, 1]]\n"),
                 {"bad.toml:7:1", "particle id 0", "missing required key 'material'"});
  expect_refused(head_with("[[generate]]\nmaterial = \"m\"\nregion = [[0, 0], [5, 5]]\n"
                           "size = 1\n"),
                 {"bad.toml:7:1", "[[generate]] #1", "missing required key 'kind'"});
  expect_refused(head_with("[[generate]]\nkind = \"random\"\nmaterial = \"m\"\nsize = 1\n"),
                 {"bad.toml:7:1", "missing required key 'region'"});
}

TEST(SceneRefusals, NoMaterialOrNoTriangle) {
  expect_refused("[simulation]\nsteps = 5\n", {"bad.toml", "no [[material]]"});
  expect_refused(std::string(kSceneHead), {"bad.toml", "no triangles"});
}

TEST(SceneRefusals, WrongTypes) {
  expect_refused("[simulation]\nsteps = \"100\"\n",
                 {"bad.toml:2:9", "key 'steps'", "expected an integer, got a string"});
  expect_refused("[simulation]\nsteps = 100.0\n",
                 {"bad.toml:2:9", "key 'steps'", "expected an integer, got a floating-point"});
  expect_refused(head_with("[output]\ncontacts = 1\n") + std::string(kGoodTriangle),
                 {"bad.toml:8:12", "key 'contacts'", "expected true or false"});
  expect_refused(head_with("[output]\ndir = 3\n") + std::string(kGoodTriangle),
                 {"bad.toml:8:7", "key 'dir'", "expected a string"});
  expect_refused("[simulation]\nsteps = 5\n[[material]]\nname = \"m\"\ndensity = \"heavy\"\n",
                 {"bad.toml:5:11", "key 'density'", "expected a number, got a string"});
  expect_refused(with_triangle("material = \"m\"\nvertices = 3\n"),
                 {"bad.toml:9:12", "particle id 0", "key 'vertices'", "expected an array of 3"});
  expect_refused(with_triangle("material = \"m\"\nvertices = [[0, 0], [1, 0]]\n"),
                 {"bad.toml:9:", "key 'vertices'", "got 2 element(s)"});
  expect_refused(with_triangle("material = \"m\"\nvertices = [[0, 0], [1, 0], [0, \"1\"]]\n"),
                 {"bad.toml:9:", "key 'vertices'", "expected a number, got a string"});
  expect_refused(with_triangle("material = \"m\"\nvertices = [[0, 0], [1, 0], [0, 1]]\n"
                               "velocity = [1]\n"),
                 {"bad.toml:10:", "key 'velocity'", "pair [x, y]"});
  expect_refused(with_triangle("material = 1\nvertices = [[0, 0], [1, 0], [0, 1]]\n"),
                 {"bad.toml:8:", "key 'material'", "expected a string"});
}

TEST(SceneRefusals, NonFiniteNumbers) {
  expect_refused("[simulation]\nsteps = 5\n[[material]]\nname = \"m\"\ndensity = inf\n",
                 {"bad.toml:5:11", "key 'density'", "finite"});
  expect_refused("[simulation]\nsteps = 5\ngravity = [0, -inf]\n",
                 {"bad.toml:3:", "key 'gravity'", "finite"});
  expect_refused(with_triangle("material = \"m\"\nvertices = [[0, 0], [nan, 0], [0, 1]]\n"),
                 {"bad.toml:9:", "particle id 0", "key 'vertices'", "finite"});
}

TEST(SceneRefusals, DegenerateTriangles) {
  const std::string two = std::string(kGoodTriangle) + "[[triangle]]\n";
  expect_refused(with_triangle("material = \"m\"\nvertices = [[0, 0], [1, 1], [2, 2]]\n"),
                 {"bad.toml:9:", "[[triangle]] #1 (particle id 0)", "key 'vertices'",
                  "degenerate"});
  // Second triangle: a repeated vertex, zero area.
  expect_refused(head_with(two + "material = \"m\"\nvertices = [[0, 0], [0, 0], [1, 1]]\n"),
                 {"bad.toml:12:", "[[triangle]] #2 (particle id 1)", "degenerate"});
  // A sliver just under the relative threshold (area/L^2 = 5e-13).
  expect_refused(with_triangle("material = \"m\"\nvertices = [[0, 0], [1, 0], [0.5, 1e-12]]\n"),
                 {"particle id 0", "degenerate"});
}

TEST(SceneRefusals, NonPositiveDensityOrPenalty) {
  const std::string mat = "[simulation]\nsteps = 5\n[[material]]\nname = \"m\"\n";
  expect_refused(mat + "density = 0\npenalty = 1\n", {"bad.toml:5:", "key 'density'", "> 0"});
  expect_refused(mat + "density = -3.5\npenalty = 1\n", {"bad.toml:5:", "key 'density'"});
  expect_refused(mat + "density = 1\npenalty = 0\n", {"bad.toml:6:", "key 'penalty'", "> 0"});
  expect_refused(mat + "density = 1\npenalty = -1e6\n", {"bad.toml:6:", "key 'penalty'"});
  expect_refused(mat + "density = 1\npenalty = 1\ntangential_penalty = 0\n",
                 {"bad.toml:7:", "key 'tangential_penalty'"});
}

TEST(SceneRefusals, OtherMaterialRanges) {
  const std::string mat = "[simulation]\nsteps = 5\n[[material]]\nname = \"m\"\n"
                          "density = 1\npenalty = 1\n";
  expect_refused(mat + "friction = -0.1\n", {"bad.toml:7:", "key 'friction'"});
  expect_refused(mat + "damping = 1\n", {"bad.toml:7:", "key 'damping'", "[0, 1)"});
  expect_refused(mat + "restitution = 0\n", {"bad.toml:7:", "key 'restitution'", "(0, 1]"});
  expect_refused(mat + "restitution = 1.2\n", {"bad.toml:7:", "key 'restitution'"});
  // restitution replaces damping: both in one material is ambiguous.
  expect_refused(mat + "restitution = 0.5\ndamping = 0.2\n",
                 {"bad.toml:8:", "key 'damping'", "not both"});
  expect_refused("[simulation]\nsteps = 5\n[[material]]\nname = \"\"\n",
                 {"bad.toml:4:", "key 'name'", "empty"});
}

TEST(SceneRefusals, UnknownMaterial) {
  expect_refused(with_triangle("material = \"sand\"\nvertices = [[0, 0], [1, 0], [0, 1]]\n"),
                 {"bad.toml:8:12", "particle id 0", "key 'material'", "unknown material \"sand\"",
                  "\"m\""});
  expect_refused(head_with("[[generate]]\nkind = \"lattice\"\nmaterial = \"sand\"\n"
                           "region = [[0, 0], [5, 5]]\nsize = 1\n"),
                 {"bad.toml:9:", "[[generate]] #1", "unknown material \"sand\""});
}

TEST(SceneRefusals, DuplicateMaterialName) {
  expect_refused(head_with("[[material]]\nname = \"m\"\ndensity = 1\npenalty = 1\n") +
                     std::string(kGoodTriangle),
                 {"bad.toml:8:", "[[material]] #2", "key 'name'", "duplicate material name \"m\""});
}

TEST(SceneRefusals, BadEnumStrings) {
  expect_refused("[simulation]\nsteps = 5\nbackend = \"gpu\"\n",
                 {"bad.toml:3:11", "key 'backend'", "unknown value \"gpu\"", "\"cuda\""});
  expect_refused("[simulation]\nsteps = 5\nprecision = \"half\"\n",
                 {"bad.toml:3:", "key 'precision'", "\"float\""});
  expect_refused("[simulation]\nsteps = 5\nmethod = \"tree\"\n",
                 {"bad.toml:3:", "key 'method'", "\"all-pairs\""});
  expect_refused("[simulation]\nsteps = 5\n[output]\nvtk_encoding = \"zip\"\n",
                 {"bad.toml:4:", "key 'vtk_encoding'", "\"ascii\""});
  expect_refused(with_triangle("material = \"m\"\nvertices = [[0, 0], [1, 0], [0, 1]]\n"
                               "motion = \"moving\"\n"),
                 {"bad.toml:10:", "particle id 0", "key 'motion'", "\"prescribed\""});
  expect_refused(head_with("[[generate]]\nkind = \"hex\"\n"),
                 {"bad.toml:8:", "key 'kind'", "\"lattice\", \"random\""});
}

TEST(SceneRefusals, StepsNotPositive) {
  expect_refused("[simulation]\nsteps = 0\n", {"bad.toml:2:9", "key 'steps'", "> 0"});
  expect_refused("[simulation]\nsteps = -5\n", {"bad.toml:2:9", "key 'steps'", "> 0"});
}

TEST(SceneRefusals, DtNotPositive) {
  expect_refused("[simulation]\nsteps = 5\ndt = 0\n", {"bad.toml:3:6", "key 'dt'", "> 0"});
  expect_refused("[simulation]\nsteps = 5\ndt = -1e-3\n", {"bad.toml:3:6", "key 'dt'"});
}

TEST(SceneRefusals, SettingRanges) {
  expect_refused("[simulation]\nsteps = 5\nsafety = 0\n", {"bad.toml:3:", "key 'safety'"});
  expect_refused("[simulation]\nsteps = 5\nsafety = 1.5\n", {"bad.toml:3:", "key 'safety'"});
  expect_refused("[simulation]\nsteps = 5\nlocal_damping = 1\n",
                 {"bad.toml:3:", "key 'local_damping'"});
  expect_refused("[simulation]\nsteps = 5\nskin = -0.1\n", {"bad.toml:3:", "key 'skin'"});
  expect_refused("[simulation]\nsteps = 5\nskin = 2\n", {"bad.toml:3:", "key 'skin'"});
  expect_refused("[simulation]\nsteps = 5\n[output]\nevery = -1\n",
                 {"bad.toml:4:", "key 'every'"});
  expect_refused("[simulation]\nsteps = 5\nmax_penetration = 0\n",
                 {"bad.toml:3:", "key 'max_penetration'"});
  expect_refused("[simulation]\nsteps = 5\nmax_penetration = 1.5\n",
                 {"bad.toml:3:", "key 'max_penetration'"});
  expect_refused("[simulation]\nsteps = 5\n[output]\ncheckpoint_every = -1\n",
                 {"bad.toml:4:", "key 'checkpoint_every'"});
}

TEST(SceneRefusals, FrameArraysNotKnownTwiceOrWithoutTheirContacts) {
  const std::string head = "[simulation]\nsteps = 5\n[output]\n";
  expect_refused(head + "frame_arrays = [\"velocity\", \"speed\"]\n",
                 {"bad.toml:4:", "key 'frame_arrays'", "\"speed\"", "\"angular_velocity\""});
  expect_refused(head + "contact_arrays = [\"force\", \"force\"]\n",
                 {"bad.toml:4:", "key 'contact_arrays'", "twice"});
  expect_refused(head + "contact_arrays = \"force\"\n",
                 {"bad.toml:4:", "key 'contact_arrays'", "an array of names"});
  expect_refused(head + "frame_arrays = [1]\n", {"bad.toml:4:", "key 'frame_arrays'", "a string"});
  // The grain's stress is a sum over the frame's contacts.
  expect_refused(head + "contacts = false\nframe_arrays = [\"velocity\", \"coordination\"]\n",
                 {"bad.toml:5:", "key 'frame_arrays'", "\"coordination\"", "contacts = true"});
}

TEST(SceneRefusals, FixedTriangleThatMoves) {
  expect_refused(with_triangle("material = \"m\"\nvertices = [[0, 0], [1, 0], [0, 1]]\n"
                               "fixed = true\nvelocity = [1, 0]\n"),
                 {"bad.toml:11:", "particle id 0", "key 'velocity'", "fixed"});
  expect_refused(with_triangle("material = \"m\"\nvertices = [[0, 0], [1, 0], [0, 1]]\n"
                               "motion = \"fixed\"\nangular_velocity = 2\n"),
                 {"bad.toml:11:", "particle id 0", "key 'angular_velocity'"});
}

TEST(SceneRefusals, FixedConflictsWithMotion) {
  expect_refused(with_triangle("material = \"m\"\nvertices = [[0, 0], [1, 0], [0, 1]]\n"
                               "fixed = true\nmotion = \"prescribed\"\n"),
                 {"bad.toml:11:", "particle id 0", "key 'motion'", "conflicts with fixed = true"});
  expect_refused(with_triangle("material = \"m\"\nvertices = [[0, 0], [1, 0], [0, 1]]\n"
                               "fixed = false\nmotion = \"fixed\"\n"),
                 {"bad.toml:11:", "key 'motion'", "conflicts with fixed = false"});
}

TEST(SceneRefusals, GeneratorKeys) {
  const std::string gen = head_with("[[generate]]\nmaterial = \"m\"\n");  // lines 7-8
  expect_refused(gen + "kind = \"lattice\"\nregion = [[0, 0], [5, 5]]\nsize = 1\nseed = 3\n",
                 {"bad.toml:12:", "[[generate]] #1", "key 'seed'", "only to kind = \"random\""});
  expect_refused(gen + "kind = \"lattice\"\nregion = [[5, 0], [0, 5]]\nsize = 1\n",
                 {"bad.toml:10:", "key 'region'", "must exceed min"});
  expect_refused(gen + "kind = \"lattice\"\nregion = [[0, 0], [5, 5]]\nsize = 0\n",
                 {"bad.toml:11:", "key 'size'", "> 0"});
  expect_refused(gen + "kind = \"lattice\"\nregion = [[0, 0], [5, 5]]\nsize = 1\ngap = -1\n",
                 {"bad.toml:12:", "key 'gap'", ">= 0"});
  expect_refused(gen + "kind = \"random\"\nregion = [[0, 0], [5, 5]]\nsize = 1\n"
                       "irregularity = 1\n",
                 {"bad.toml:12:", "key 'irregularity'", "[0, 1)"});
  expect_refused(gen + "kind = \"random\"\nregion = [[0, 0], [5, 5]]\nsize = 1\nseed = -1\n",
                 {"bad.toml:12:", "key 'seed'", ">= 0"});
  expect_refused(gen + "kind = \"random\"\nregion = [[0, 0], [5, 5]]\nsize = 1\ncount = -1\n",
                 {"bad.toml:12:", "key 'count'", ">= 0"});
  expect_refused(gen + "kind = \"random\"\nregion = [[0, 0], [5, 5]]\nsize = 1\ncount = 1000\n",
                 {"bad.toml:12:", "key 'count'", "asks for 1000 triangles"});
}

TEST(SceneRefusals, GeneratorMakingNoneOrTooMany) {
  const std::string gen = head_with("[[generate]]\nmaterial = \"m\"\n");
  expect_refused(gen + "kind = \"lattice\"\nregion = [[0, 0], [0.5, 0.5]]\nsize = 1\n",
                 {"bad.toml:11:", "[[generate]] #1", "key 'size'", "no whole triangle"});
  expect_refused(gen + "kind = \"random\"\nregion = [[0, 0], [0.5, 0.5]]\nsize = 1\n",
                 {"bad.toml:11:", "key 'size'", "no whole triangle"});
  expect_refused(gen + "kind = \"random\"\nregion = [[0, 0], [1000, 1000]]\nsize = 1e-3\n",
                 {"bad.toml:11:", "key 'size'", "more than the limit"});
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
