// [[mesh]] and the bond keys of [[material]] (issue 14): a disc, a rectangle and a polygon
// meshed by Gmsh, a .msh file, the bonds of shared edges, and the refusals with their messages.
#include "io/scene/scene_sections.hpp"
#include "scene_refusal.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using test::expect_refused;

#ifdef TRIDEM_HAS_GMSH
constexpr bool kHasGmsh = true;
#else
constexpr bool kHasGmsh = false;
#endif

constexpr std::string_view kGranite = "[simulation]\n"
                                      "steps = 5\n"
                                      "[[material]]\n"
                                      "name = \"granite\"\n"
                                      "density = 2650\n"
                                      "penalty = 5e10\n"
                                      "friction = 0.6\n"
                                      "young_modulus = 40e9\n"
                                      "tensile_strength = 8e6\n"
                                      "shear_strength = 25e6\n"
                                      "friction_angle = 35\n"
                                      "fracture_energy = 30\n"
                                      "shear_fracture_energy = 150\n";

std::string with_mesh(std::string_view mesh) {
  return std::string(kGranite) + "[[mesh]]\n" + std::string(mesh);
}

double area_of(const TriangleSpec& t) {
  return 0.5 * cross(t.vertices[1] - t.vertices[0], t.vertices[2] - t.vertices[0]);
}

TEST(SceneMesh, BondKeysOfAMaterial) {
  const Scene s = parse_scene(std::string(kGranite) + "[[triangle]]\nmaterial = \"granite\"\n"
                                                      "vertices = [[0, 0], [1, 0], [0, 1]]\n",
                              "s.toml");
  const Material& m = s.materials[0];
  EXPECT_TRUE(m.bondable());
  EXPECT_EQ(m.young_modulus, 40e9);
  EXPECT_EQ(m.tensile_strength, 8e6);
  EXPECT_EQ(m.shear_strength, 25e6);
  EXPECT_EQ(m.friction_angle, 35);
  EXPECT_EQ(m.fracture_energy, 30);
  EXPECT_EQ(m.shear_fracture_energy, 150);
  EXPECT_TRUE(s.bonds.empty());
}

TEST(SceneMesh, PartialBondKeysAreRefused) {
  expect_refused(std::string(test::kSceneHead) + "young_modulus = 1e9\n" +
                     std::string(test::kGoodTriangle),
                 {"[[material]] #1", "young_modulus", "tensile_strength is missing"});
  std::string bad(kGranite);
  bad.replace(bad.find("fracture_energy = 30"), 20, "fracture_energy = -1");
  expect_refused(bad + std::string(test::kGoodTriangle), {"fracture_energy", "must be > 0"});
}

TEST(SceneMesh, DiscIsMeshedAndBonded) {
  if (!kHasGmsh) GTEST_SKIP() << "built with -DTRIDEM_WITH_GMSH=OFF";
  const Scene s = parse_scene(with_mesh("kind = \"disc\"\ncenter = [0.1, 0.2]\nradius = 0.025\n"
                                        "size = 0.005\nmaterial = \"granite\"\nbonded = true\n"),
                              "s.toml");
  ASSERT_GT(s.triangles.size(), 50u);
  double area = 0;
  for (const TriangleSpec& t : s.triangles) {
    EXPECT_GT(area_of(t), 0);  // counter-clockwise
    area += area_of(t);
    for (const Vec2d& v : t.vertices) EXPECT_LE(norm(v - Vec2d{0.1, 0.2}), 0.025 * (1 + 1e-9));
  }
  // The polygon inscribed in the circle: a little less than pi r^2.
  EXPECT_NEAR(area, M_PI * 0.025 * 0.025, 0.01 * M_PI * 0.025 * 0.025);
  // Euler: a triangulated disc has (3 T - boundary edges) / 2 interior edges; every
  // interior edge is one bond, each triangle has at most three.
  const std::size_t t = s.triangles.size();
  ASSERT_GT(s.bonds.size(), t);
  EXPECT_LT(s.bonds.size(), 3 * t / 2);
  std::vector<int> per(t, 0);
  std::set<std::pair<std::size_t, std::size_t>> unique;
  for (const BondSpec& b : s.bonds) {
    EXPECT_LT(b.a, b.b);
    ++per[b.a];
    ++per[b.b];
    unique.insert({b.a, b.b});
    EXPECT_GT(norm(b.q - b.p), 0.2 * 0.005);
  }
  EXPECT_EQ(unique.size(), s.bonds.size());
  for (int c : per) EXPECT_LE(c, 3);
  const std::size_t boundary = 3 * t - 2 * s.bonds.size();
  // The boundary's edges are about the circumference over the size.
  EXPECT_NEAR(static_cast<double>(boundary), 2 * M_PI * 0.025 / 0.005, 8);
}

TEST(SceneMesh, RectangleWithoutBondsIsLooseTriangles) {
  if (!kHasGmsh) GTEST_SKIP() << "built with -DTRIDEM_WITH_GMSH=OFF";
  const Scene s = parse_scene(with_mesh("kind = \"rectangle\"\nregion = [[0, 0], [0.04, 0.02]]\n"
                                        "size = 0.004\nmaterial = \"granite\"\n"),
                              "s.toml");
  double area = 0;
  for (const TriangleSpec& t : s.triangles) area += area_of(t);
  EXPECT_NEAR(area, 0.04 * 0.02, 1e-12);
  EXPECT_TRUE(s.bonds.empty());
  // The same rectangle bonded: the same triangles, now bonded.
  const Scene b = parse_scene(with_mesh("kind = \"rectangle\"\nregion = [[0, 0], [0.04, 0.02]]\n"
                                        "size = 0.004\nmaterial = \"granite\"\nbonded = true\n"),
                              "s.toml");
  EXPECT_EQ(b.triangles.size(), s.triangles.size());
  EXPECT_GT(b.bonds.size(), b.triangles.size());
}

// A notched beam's outline (the notched beam of docs/fracture.md): the mesh fills the
// polygon and leaves its notch empty, the notch's tip is a node, and no bond crosses the
// notch (its two flanks are free faces).
TEST(SceneMesh, PolygonIsMeshedWithItsNotch) {
  if (!kHasGmsh) GTEST_SKIP() << "built with -DTRIDEM_WITH_GMSH=OFF";
  const Scene s = parse_scene(
      with_mesh("kind = \"polygon\"\npolygon = [[-0.03, 0], [-0.001, 0], [-0.001, 0.006], "
                "[0, 0.007], [0.001, 0.006], [0.001, 0], [0.03, 0], [0.03, 0.015], "
                "[-0.03, 0.015]]\nsize = 0.002\nmaterial = \"granite\"\nbonded = true\n"),
      "s.toml");
  // The beam less the notch: a 2 mm slot 6 mm deep and its tip's triangle, 1 mm high.
  const double expected = 0.06 * 0.015 - 0.002 * 0.006 - 0.5 * 0.002 * 0.001;
  double area = 0;
  bool tip = false;
  for (const TriangleSpec& t : s.triangles) {
    EXPECT_GT(area_of(t), 0);
    area += area_of(t);
    const Vec2d c = (t.vertices[0] + t.vertices[1] + t.vertices[2]) / 3.0;
    EXPECT_FALSE(std::abs(c.x) < 0.001 && c.y < 0.006) << "a triangle in the notch";
    for (const Vec2d& v : t.vertices) tip = tip || (v.x == 0 && v.y == 0.007);
  }
  EXPECT_NEAR(area, expected, 1e-12);
  EXPECT_TRUE(tip);
  for (const BondSpec& b : s.bonds)
    EXPECT_FALSE(std::abs(0.5 * (b.p.x + b.q.x)) < 1e-12 && std::max(b.p.y, b.q.y) <= 0.006)
        << "a bond across the notch";
  expect_refused(with_mesh("kind = \"polygon\"\npolygon = [[0, 0], [1, 1], [1, 0], [0, 1]]\n"
                           "size = 0.1\nmaterial = \"granite\"\n"),
                 {"[[mesh]] #1", "polygon", "intersects itself"});
  expect_refused(with_mesh("kind = \"polygon\"\npolygon = [[0, 0], [1, 0]]\n"
                           "size = 0.1\nmaterial = \"granite\"\n"),
                 {"polygon", "at least 3 points"});
  expect_refused(with_mesh("kind = \"polygon\"\npolygon = [[0, 0], [1, 0], [1, 0.1]]\n"
                           "size = 0.2\nmaterial = \"granite\"\n"),
                 {"size", "bounding box"});
  expect_refused(with_mesh("kind = \"polygon\"\nsize = 0.1\nmaterial = \"granite\"\n"),
                 {"polygon"});
  expect_refused(with_mesh("kind = \"polygon\"\npolygon = [[0, 0], [1, 0], [1, 1]]\n"
                           "region = [[0, 0], [1, 1]]\nsize = 0.1\nmaterial = \"granite\"\n"),
                 {"region"});
}

TEST(SceneMesh, MeshFileIsBonded) {
  if (!kHasGmsh) GTEST_SKIP() << "built with -DTRIDEM_WITH_GMSH=OFF";
  const std::string mesh = std::string(TRIDEM_SOURCE_DIR) + "/tests/data/mesh/two_grains.msh";
  const Scene s = parse_scene(with_mesh("kind = \"file\"\nfile = \"" + mesh +
                                        "\"\nmaterial = \"granite\"\nbonded = true\n"),
                              "s.toml");
  EXPECT_GT(s.triangles.size(), 2u);
  EXPECT_FALSE(s.bonds.empty());
  EXPECT_FALSE(s.has_bodies());
}

// A flattened disc (the Brazilian test's loading, docs/fracture.md): its top and bottom are
// flat chords of the given angle, every vertex within the disc, the flats' vertices at
// y = +-r cos(angle / 2) and none beyond; the edges take many directions (Delaunay).
TEST(SceneMesh, FlattenedDiscHasItsFlats) {
  if (!kHasGmsh) GTEST_SKIP() << "built with -DTRIDEM_WITH_GMSH=OFF";
  const double r = 0.025, y = r * std::cos(10 * M_PI / 180);
  const Scene s = parse_scene(with_mesh("kind = \"disc\"\ncenter = [0, 0]\nradius = 0.025\n"
                                        "size = 0.005\nflat_angle = 20\nmaterial = \"granite\"\n"
                                        "bonded = true\n"),
                              "s.toml");
  double top = -1, bottom = 1;
  int on_top = 0;
  std::set<int> directions;  // the edges' directions, in 10-degree bins
  for (const TriangleSpec& t : s.triangles)
    for (std::size_t k = 0; k < 3; ++k) {
      const Vec2d v = t.vertices[k], w = t.vertices[(k + 1) % 3];
      EXPECT_LE(norm(v), r * (1 + 1e-9));
      top = std::max(top, v.y);
      bottom = std::min(bottom, v.y);
      on_top += std::abs(v.y - y) < 1e-12;
      directions.insert(static_cast<int>(
          std::fmod(std::atan2(w.y - v.y, w.x - v.x) * 180 / M_PI + 180, 180) / 10));
    }
  EXPECT_NEAR(top, y, 1e-12);
  EXPECT_NEAR(bottom, -y, 1e-12);
  EXPECT_GE(on_top, 2);
  EXPECT_GE(directions.size(), 15u) << "a lattice-like mesh has its edges in a few directions";
  expect_refused(with_mesh("kind = \"disc\"\ncenter = [0, 0]\nradius = 1\nsize = 0.1\n"
                           "flat_angle = 120\nmaterial = \"granite\"\n"),
                 {"flat_angle", "[0, 90]"});
  expect_refused(with_mesh("kind = \"rectangle\"\nregion = [[0, 0], [1, 1]]\nsize = 0.1\n"
                           "flat_angle = 10\nmaterial = \"granite\"\n"),
                 {"flat_angle", "disc"});
}

TEST(SceneMesh, RefusalsSayWhatToChange) {
  expect_refused(with_mesh("kind = \"sphere\"\nmaterial = \"granite\"\n"),
                 {"[[mesh]] #1", "kind", "sphere"});
  expect_refused(with_mesh("kind = \"disc\"\ncenter = [0, 0]\nradius = -1\nsize = 0.1\n"
                           "material = \"granite\"\n"),
                 {"radius", "must be > 0"});
  expect_refused(with_mesh("kind = \"disc\"\ncenter = [0, 0]\nradius = 1\nsize = 1e-6\n"
                           "material = \"granite\"\n"),
                 {"size", "more than the limit"});
  expect_refused(with_mesh("kind = \"rectangle\"\nregion = [[1, 0], [0, 1]]\nsize = 0.1\n"
                           "material = \"granite\"\n"),
                 {"region", "must exceed"});
  expect_refused(with_mesh("kind = \"file\"\nfile = \"nowhere.msh\"\nmaterial = \"granite\"\n"),
                 {"[[mesh]] #1", "file"});
  expect_refused(with_mesh("kind = \"disc\"\ncenter = [0, 0]\nradius = 1\nsize = 0.1\n"
                           "material = \"granite\"\ncolour = 1\n"),
                 {"colour"});
  // Bonded needs the bond keys.
  expect_refused(std::string(test::kSceneHead) +
                     "[[mesh]]\nkind = \"disc\"\ncenter = [0, 0]\nradius = 1\nsize = 0.1\n"
                     "material = \"m\"\nbonded = true\n",
                 {"bonded", "no bond properties", "young_modulus"});
}

TEST(SceneMesh, ABuildWithoutGmshRefusesAMesh) {
  if (kHasGmsh) GTEST_SKIP() << "built with Gmsh";
  expect_refused(with_mesh("kind = \"disc\"\ncenter = [0, 0]\nradius = 1\nsize = 0.1\n"
                           "material = \"granite\"\n"),
                 {"[[mesh]] #1", "-DTRIDEM_WITH_GMSH=OFF"});
}

TEST(SceneMesh, SharedEdgesBecomeBonds) {
  // Two triangles of a unit square share its diagonal; a third touches at a vertex only.
  std::vector<TriangleSpec> t(3);
  t[0].vertices = {Vec2d{0, 0}, Vec2d{1, 0}, Vec2d{1, 1}};
  t[1].vertices = {Vec2d{0, 0}, Vec2d{1, 1}, Vec2d{0, 1}};
  t[2].vertices = {Vec2d{1, 1}, Vec2d{2, 1}, Vec2d{2, 2}};
  const std::vector<BondSpec> b = scene_detail::shared_edge_bonds(t, 0);
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(b[0].a, 0u);
  EXPECT_EQ(b[0].b, 1u);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
