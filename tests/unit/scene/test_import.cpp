// [[import]]: triangles from a CSV file (columns by name, a body column grouping members)
// and from a Gmsh mesh (tests/data/mesh/two_grains.msh, physical groups as bodies), and
// the refusals of bad files.
#include "scene_refusal.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using test::expect_refused;
using test::kSceneHead;

std::filesystem::path write_file(const std::string& name, const std::string& text) {
  // The process id keeps runs of the suite beside each other (ctest -j, other builds) apart.
  auto path = std::filesystem::temp_directory_path() /
              ("tridem_import_" + std::to_string(getpid()) + "_" + name);
  std::ofstream(path) << text;
  return path;
}

std::string importing(const std::filesystem::path& file, std::string_view more = "") {
  return std::string(kSceneHead) + "[[import]]\nfile = \"" + file.string() +
         "\"\nmaterial = \"m\"\n" + std::string(more);
}

TEST(SceneImport, CsvColumnsByNameWithBodiesAndVelocities) {
  // Two members of body 7 (a unit square, rigid motion V = (1, 2), ω = 3 about its
  // centroid (0.5, 0.5): each member's centroid velocity is V + ω × r), then a lone
  // clockwise triangle.
  const auto v = [](double rx, double ry) { return std::array<double, 2>{1 - 3 * ry, 2 + 3 * rx}; };
  const auto a = v(2.0 / 3 - 0.5, 1.0 / 3 - 0.5), b = v(1.0 / 3 - 0.5, 2.0 / 3 - 0.5);
  const std::string csv = fmt::format("omega,body,x1,y1,x2,y2,x3,y3,vx,vy\n"
                                      "3,7,0,0,1,0,1,1,{:.17g},{:.17g}\n"
                                      "0.5,2,5,0,5,1,6,0,-1,0\n"
                                      "3,7,0,0,1,1,0,1,{:.17g},{:.17g}\n",
                                      a[0], a[1], b[0], b[1]);
  const Scene s = parse_scene(importing(write_file("bodies.csv", csv)), "s.toml");
  ASSERT_EQ(s.triangles.size(), 3u);
  ASSERT_EQ(s.bodies.size(), 2u);
  EXPECT_EQ(s.bodies[0].first, 0u);
  EXPECT_EQ(s.bodies[0].count, 2u);  // body 7, first seen first
  EXPECT_NEAR(s.bodies[0].velocity.x, 1, 1e-14);
  EXPECT_NEAR(s.bodies[0].velocity.y, 2, 1e-14);
  EXPECT_EQ(s.bodies[0].angular_velocity, 3);
  EXPECT_EQ(s.bodies[1].first, 2u);
  EXPECT_EQ(s.bodies[1].count, 1u);
  EXPECT_EQ(s.bodies[1].velocity.x, -1);
  EXPECT_EQ(s.triangles[2].velocity.x, -1);
  EXPECT_EQ(s.triangles[2].angular_velocity, 0.5);
  // The clockwise triangle is made counter-clockwise, as [[triangle]] does.
  EXPECT_GT(cross(s.triangles[2].vertices[1] - s.triangles[2].vertices[0],
                  s.triangles[2].vertices[2] - s.triangles[2].vertices[0]),
            0);
  EXPECT_EQ(s.triangles[2].vertices[0].x, 5);
}

TEST(SceneImport, CsvWithoutOptionalColumnsAndRelativeToTheScene) {
  const auto file = write_file("plain.csv", "x1,y1,x2,y2,x3,y3\n0,0,1,0,0,1\n\n2,0,3,0,2,1\n");
  // A relative file is found beside the scene file.
  const std::string scene_path = (file.parent_path() / "scene.toml").string();
  const Scene s = parse_scene(std::string(kSceneHead) + "[[import]]\nfile = \"" +
                                  file.filename().string() + "\"\nmaterial = \"m\"\nfixed = true\n",
                              scene_path);
  ASSERT_EQ(s.triangles.size(), 2u);
  EXPECT_TRUE(s.bodies.empty());
  EXPECT_EQ(s.triangles[1].motion, Motion::Fixed);
  EXPECT_EQ(s.triangles[1].velocity.x, 0);
}

TEST(SceneImport, CsvRefusalsNameTheFileAndLine) {
  expect_refused(importing(write_file("missing_col.csv", "x1,y1,x2,y2,x3\n0,0,1,0,0\n")),
                 {"[[import]] #1", "key 'file'", "missing_col.csv:1", "lacks column 'y3'"});
  expect_refused(importing(write_file("unknown_col.csv", "x1,y1,x2,y2,x3,y3,vz\n0,0,1,0,0,1,0\n")),
                 {"unknown column 'vz'"});
  expect_refused(
      importing(write_file("bad_number.csv", "x1,y1,x2,y2,x3,y3\n0,0,1,0,0,1\n0,0,1,x,0,1\n")),
      {"bad_number.csv:3", "column 'y2'", "\"x\""});
  expect_refused(importing(write_file("short_row.csv", "x1,y1,x2,y2,x3,y3\n0,0,1,0,0\n")),
                 {"short_row.csv:2", "5 values for the header's 6 columns"});
  expect_refused(importing(write_file("flat.csv", "x1,y1,x2,y2,x3,y3\n0,0,1,0,2,0\n")),
                 {"line 2", "degenerate"});
  expect_refused(importing(write_file("moving.csv", "x1,y1,x2,y2,x3,y3,vx\n0,0,1,0,0,1,1\n"),
                           "fixed = true\n"),
                 {"line 2", "fixed = true, but the file gives it a velocity"});
  expect_refused(importing(write_file("empty.csv", "x1,y1,x2,y2,x3,y3\n")), {"no triangles"});
  expect_refused(importing("/nonexistent/particles.csv"), {"key 'file'", "cannot open"});
  expect_refused(importing(write_file("p.txt", "")), {"key 'file'", "give format = \"csv\""});
  expect_refused(
      importing(write_file("p2.csv", "x1,y1,x2,y2,x3,y3\n0,0,1,0,0,1\n"), "bodies = [\"a\"]\n"),
      {"key 'bodies'", "applies only to a Gmsh mesh"});
  // Imported triangles overlap-checked like any: the message names the [[import]].
  expect_refused(
      importing(write_file("overlap.csv", "x1,y1,x2,y2,x3,y3\n0,0,1,0,0,1\n0.1,0.1,1,0.1,0.1,1\n")),
      {"[[import]] #1", "overlap", "keep_overlaps = true"});
  // Kept when asked (a run's final state holds its contacts' overlaps)...
  const auto kept = write_file("kept.csv", "x1,y1,x2,y2,x3,y3\n0,0,1,0,0,1\n0.1,0.1,1,0.1,0.1,1\n");
  EXPECT_EQ(parse_scene(importing(kept, "keep_overlaps = true\n"), "s.toml").triangles.size(), 2u);
  // ...but only among the imported triangles: one of them against a [[triangle]] is not.
  expect_refused(
      importing(kept, "keep_overlaps = true\n") +
          "[[triangle]]\nmaterial = \"m\"\nvertices = [[0.2, 0.2], [2, 0.2], [0.2, 2]]\n",
      {"[[triangle]] #1", "[[import]] #1", "overlap"});
}

#ifdef TRIDEM_HAS_GMSH
constexpr bool kHasGmsh = true;
#else
constexpr bool kHasGmsh = false;
#endif

TEST(SceneImport, GmshMeshIsRefusedByABuildWithoutGmsh) {
  if (kHasGmsh) GTEST_SKIP() << "built with Gmsh";
  expect_refused(importing(std::string(TRIDEM_SOURCE_DIR) + "/tests/data/mesh/two_grains.msh"),
                 {"key 'file'", "-DTRIDEM_WITH_GMSH=OFF"});
}

const std::string kMesh = std::string(TRIDEM_SOURCE_DIR) + "/tests/data/mesh/two_grains.msh";

double area_of(const TriangleSpec& t) {
  return 0.5 * cross(t.vertices[1] - t.vertices[0], t.vertices[2] - t.vertices[0]);
}

TEST(SceneImport, GmshMeshGroupsBecomeBodies) {
  if (!kHasGmsh) GTEST_SKIP() << "built with -DTRIDEM_WITH_GMSH=OFF";
  const Scene s = parse_scene(importing(kMesh, "bodies = [\"square\", \"pentagon\"]\n"), "s.toml");
  ASSERT_TRUE(s.has_bodies());
  // The two grains are bodies; the floor's triangles are on their own.
  double square = 0, pentagon = 0, lone = 0;
  std::size_t bodies = 0;
  for (const BodySpec& b : s.bodies) {
    double a = 0;
    for (std::size_t k = b.first; k < b.first + b.count; ++k) {
      EXPECT_GT(area_of(s.triangles[k]), 0);
      a += area_of(s.triangles[k]);
    }
    if (b.count > 1 && std::abs(a - 1) < 1e-12)
      square = a, ++bodies;
    else if (b.count > 1)
      pentagon = a, ++bodies;
    else
      lone += a;
  }
  EXPECT_EQ(bodies, 2u);
  EXPECT_NEAR(square, 1, 1e-12);
  // Shoelace of (2,0) (3,0) (3.3,0.9) (2.5,1.5) (1.7,0.9).
  EXPECT_NEAR(pentagon, 1.65, 1e-12);
  EXPECT_NEAR(lone, 6 * 0.5, 1e-12);  // the floor slab
}

TEST(SceneImport, GmshMeshWithoutGroupsGivesLoneTriangles) {
  if (!kHasGmsh) GTEST_SKIP() << "built with -DTRIDEM_WITH_GMSH=OFF";
  const Scene s = parse_scene(importing(kMesh), "s.toml");
  double total = 0;
  for (const TriangleSpec& t : s.triangles) total += area_of(t);
  EXPECT_NEAR(total, 1 + 1.65 + 3, 1e-12);
  EXPECT_TRUE(s.bodies.empty());
}

TEST(SceneImport, GmshRefusals) {
  if (!kHasGmsh) GTEST_SKIP() << "built with -DTRIDEM_WITH_GMSH=OFF";
  expect_refused(importing(kMesh, "bodies = [\"rock\"]\n"),
                 {"key 'file'", "no 2D physical group named \"rock\"", "\"square\""});
  expect_refused(importing(write_file("junk.msh", "this is not a mesh\n")),
                 {"key 'file'", "junk.msh"});
  expect_refused(importing("/nonexistent/m.msh"), {"no such file"});
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
