// Initial overlaps: refused by the reader and validate_scene with both particle ids and
// where they come from, touching allowed, generated scenes pass, and the check is O(n).
#include "core/initial_overlaps.hpp"
#include "scene_refusal.hpp"
#include "tridem/error.hpp"
#include "tridem/generate.hpp"
#include "tridem/scene_io.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <string>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

// Line 7: the floor, a fixed triangle whose top edge is y = 0 for x in [-1, 1].
constexpr std::string_view kFloor =
    "[[triangle]]\n"
    "material = \"m\"\n"
    "vertices = [[1, 0], [-1, 0], [0, -2]]\n"
    "fixed = true\n";

/// A grain of edge 0.1 standing on the floor, lowered by `sink` metres (line 11).
std::string grain(double sink) {
  const double y = -sink;
  return "[[triangle]]\nmaterial = \"m\"\nvertices = [[0, " + std::to_string(y) + "], [0.1, " +
         std::to_string(y) + "], [0.05, " + std::to_string(y + 0.0866) + "]]\n";
}

TEST(InitialOverlaps, GrainIntoTheFloorIsRefusedNamingBothIds) {
  const std::string text = std::string(test::kSceneHead) + std::string(kFloor) + grain(0.004);
  const std::string message = test::expect_refused(
      text, {"bad.toml: ", "particle id 0 ([[triangle]] #1 at bad.toml:7:1)",
             "particle id 1 ([[triangle]] #2 at bad.toml:11:1)", "overlap by 0.004 m",
             "relax_overlaps = true"});
}

TEST(InitialOverlaps, GeneratedTrianglesAreNamedByTheirBlock) {
  // A lattice whose first row sinks 1 mm into the floor.
  const std::string text = std::string(test::kSceneHead) + std::string(kFloor) +
                           "[[generate]]\nkind = \"lattice\"\nmaterial = \"m\"\n"
                           "region = [[-0.5, -0.001], [0.5, 0.3]]\nsize = 0.1\n";
  test::expect_refused(text, {"particle id 0 ([[triangle]] #1 at bad.toml:7:1)",
                              "particle id 1 ([[generate]] #1 at bad.toml:11:1, its triangle 1 of",
                              "overlap by 0.001 m"});
}

TEST(InitialOverlaps, TouchingIsAllowed) {
  EXPECT_NO_THROW(parse_scene(std::string(test::kSceneHead) + std::string(kFloor) + grain(0),
                              "touch.toml"));
  // A lattice with gap = 0: edges of neighbours coincide, up to rounding.
  EXPECT_NO_THROW(parse_scene(std::string(test::kSceneHead) +
                                  "[[generate]]\nkind = \"lattice\"\nmaterial = \"m\"\n"
                                  "region = [[1000, 3], [1004, 5]]\nsize = 0.25\ngap = 0\n",
                              "lattice.toml"));
  // A grain resting 1e-12 m into the floor is within rounding of touching: accepted.
  EXPECT_NO_THROW(parse_scene(std::string(test::kSceneHead) + std::string(kFloor) + grain(1e-12),
                              "touch.toml"));
}

TEST(InitialOverlaps, RelaxOverlapsLetsTheReaderAcceptThem) {
  std::string text = std::string(test::kSceneHead) + std::string(kFloor) + grain(0.004);
  text.insert(text.find("steps = 5\n") + 10, "relax_overlaps = true\n");
  const Scene s = parse_scene(text, "relax.toml");
  EXPECT_TRUE(s.simulation.relax_overlaps);
  EXPECT_FALSE(parse_scene(std::string(test::kSceneHead) + std::string(test::kGoodTriangle),
                           "default.toml")
                   .simulation.relax_overlaps);
}

TEST(InitialOverlaps, WallsMayOverlapEachOther) {
  // Two walls never interact (pairs of walls are skipped), so their overlap holds no energy.
  const std::string text = std::string(test::kSceneHead) + std::string(kFloor) +
                           "[[triangle]]\nmaterial = \"m\"\nvertices = [[0, -0.5], [2, -0.5], "
                           "[1, 1]]\nfixed = true\n";
  EXPECT_NO_THROW(parse_scene(text, "walls.toml"));
}

TEST(InitialOverlaps, ValidateSceneRefusesACodeBuiltSceneByParticleId) {
  const Scene s = parse_scene(std::string(test::kSceneHead) + std::string(kFloor) + grain(0),
                              "touch.toml");
  Scene sunk = s;
  for (auto& v : sunk.triangles[1].vertices) v.y -= 0.01;
  sunk.source.clear();
  try {
    validate_scene(sunk);
    ADD_FAILURE() << "accepted";
  } catch (const SceneError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("scene built in code: particle id 0 and particle id 1 overlap by "
                           "0.01 m"),
              std::string::npos)
        << message;
  }
}

// The exact test, not the direct-area one: a star of David has no vertex inside the other.
TEST(InitialOverlaps, EdgeCrossingsWithNoVertexInsideAreFound) {
  std::vector<TriangleSpec> ts(2);
  ts[0].vertices = {Vec2d{0, 1}, Vec2d{-0.866, -0.5}, Vec2d{0.866, -0.5}};
  ts[1].vertices = {Vec2d{0, -1}, Vec2d{0.866, 0.5}, Vec2d{-0.866, 0.5}};
  const auto o = first_initial_overlap(ts);
  ASSERT_TRUE(o);
  EXPECT_EQ(o->a, 0u);
  EXPECT_EQ(o->b, 1u);
  // Along an edge normal, the other triangle must move by its whole height inside it.
  EXPECT_NEAR(o->depth, 1.0, 1e-4);
}

// Every overlap, found on the threads, comes in one order whatever their number: a grid of
// grains each overlapping its right and upper neighbours, against one thread.
TEST(InitialOverlaps, TheOverlapsFoundOnThreadsAreTheSameOnAnyNumberOfThreads) {
  std::vector<TriangleSpec> ts;
  for (int row = 0; row < 60; ++row)
    for (int column = 0; column < 60; ++column) {
      const double x = 0.09 * column + 0.01 * (row % 3), y = 0.08 * row;
      TriangleSpec t;
      t.vertices = {Vec2d{x, y}, Vec2d{x + 0.1, y}, Vec2d{x + 0.05, y + 0.0866}};
      ts.push_back(t);
    }
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  const std::vector<InitialOverlap> one = find_initial_overlaps(ts);
  ASSERT_GT(one.size(), 3000u);
  for (int threads : {2, 3, 4}) {
    omp_set_num_threads(threads);
    const std::vector<InitialOverlap> many = find_initial_overlaps(ts);
    ASSERT_EQ(many.size(), one.size()) << threads << " threads";
    for (std::size_t k = 0; k < one.size(); ++k) {
      ASSERT_EQ(many[k].a, one[k].a) << k;
      ASSERT_EQ(many[k].b, one[k].b) << k;
      ASSERT_EQ(many[k].depth, one[k].depth) << k;
      ASSERT_EQ(many[k].push.x, one[k].push.x) << k;
    }
  }
  omp_set_num_threads(saved);

  // The first pair a filter accepts is the first such pair of the whole list, on any
  // number of threads, and the pairs it refuses are left out.
  auto counts = [](std::size_t a, std::size_t b) { return a >= 1000 && (a + b) % 7 == 3; };
  const auto want = std::find_if(one.begin(), one.end(),
                                 [&](const InitialOverlap& o) { return counts(o.a, o.b); });
  ASSERT_NE(want, one.end());
  for (int threads : {1, 2, 4}) {
    omp_set_num_threads(threads);
    const std::optional<InitialOverlap> first = first_initial_overlap_where(ts, {}, counts);
    ASSERT_TRUE(first) << threads << " threads";
    EXPECT_EQ(first->a, want->a);
    EXPECT_EQ(first->b, want->b);
    EXPECT_EQ(first->depth, want->depth);
  }
  omp_set_num_threads(saved);
  EXPECT_FALSE(first_initial_overlap_where(ts, {}, [](std::size_t, std::size_t) { return false; }));
}

TEST(InitialOverlaps, GeneratedScenesDoNotOverlap) {
  for (double gap : {0.0, 0.05, 0.3}) {
    const auto lattice = generate_lattice(LatticeSpec{0, {0, 0}, {3, 2}, 0.1, gap, {}});
    EXPECT_FALSE(first_initial_overlap(lattice)) << "lattice, gap " << gap;
    for (double irregularity : {0.0, 0.5, 0.9}) {
      const auto random =
          generate_random(RandomPackingSpec{0, {0, 0}, {3, 2}, 0.1, gap, {}, 7, 0, irregularity});
      EXPECT_FALSE(first_initial_overlap(random)) << "random, gap " << gap << " irr "
                                                  << irregularity;
    }
  }
}

// Through a periodic boundary a grain touches its neighbour's image: two grains at the two
// ends of the cell that overlap only through it are refused, and relax_overlaps pushes
// them apart across it (the solvers would see the overlap from the first step).
constexpr std::string_view kAcrossTheBoundary =
    "[[triangle]]\nmaterial = \"m\"\nvertices = [[0.005, 0], [0.1, 0], [0.05, 0.0866]]\n"
    "[[triangle]]\nmaterial = \"m\"\nvertices = [[0.93, 0], [1.03, 0], [0.98, 0.0866]]\n";

std::string periodic_scene(std::string_view cell) {
  std::string text = std::string(test::kSceneHead) + std::string(kAcrossTheBoundary);
  text.insert(text.find("steps = 5\n") + 10, std::string(cell));
  return text;
}

TEST(InitialOverlaps, OverlapThroughAPeriodicBoundaryIsRefused) {
  // Without the cell they are 0.83 m apart.
  EXPECT_NO_THROW(parse_scene(periodic_scene(""), "open.toml"));
  test::expect_refused(periodic_scene("periodic_x = [0.0, 1.0]\n"),
                       {"particle id 0 ([[triangle]] #1 at bad.toml:8:1)",
                        "particle id 1 ([[triangle]] #2 at bad.toml:11:1)", "overlap by"});
  // A cell one grain longer: they no longer meet.
  EXPECT_NO_THROW(parse_scene(periodic_scene("periodic_x = [0.0, 1.1]\n"), "long.toml"));
  // Through periodic_y the same, the pair turned by 90 degrees.
  std::vector<TriangleSpec> turned = parse_scene(periodic_scene(""), "open.toml").triangles;
  for (TriangleSpec& t : turned)
    for (Vec2d& v : t.vertices) v = {-v.y, v.x};
  PeriodicCell cell;
  cell.y = PeriodicRange{0, 1};
  EXPECT_TRUE(find_initial_overlaps(turned).empty());
  const std::vector<InitialOverlap> found = find_initial_overlaps(turned, cell);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].a, 0u);
  EXPECT_EQ(found[0].b, 1u);
  EXPECT_GT(found[0].depth, 0.01);
}

TEST(InitialOverlaps, RelaxOverlapsPushesApartThroughAPeriodicBoundary) {
  Scene s =
      parse_scene(periodic_scene("periodic_x = [0.0, 1.0]\nrelax_overlaps = true\n"), "relax.toml");
  const std::vector<InitialOverlap> before =
      find_initial_overlaps(s.triangles, s.simulation.periodic);
  ASSERT_EQ(before.size(), 1u);
  const RelaxReport r = relax_initial_overlaps(s);
  EXPECT_EQ(r.pairs, 1u);
  EXPECT_EQ(r.moved, 2u);
  EXPECT_TRUE(find_initial_overlaps(s.triangles, s.simulation.periodic).empty());
  // Pushed apart through the boundary: grain 0 to the right, grain 1 to the left.
  EXPECT_GT(s.triangles[0].vertices[0].x, 0.005);
  EXPECT_LT(s.triangles[1].vertices[0].x, 0.93);
}

// The check bins by the solvers' cell grid: O(n). About 250,000 triangles take a fraction
// of a second; an O(n²) check would take minutes.
TEST(InitialOverlaps, LargeGeneratedSceneIsCheckedFast) {
  const auto ts =
      generate_random(RandomPackingSpec{0, {0, 0}, {63.3, 63.3}, 0.1, 0.1, {}, 3, 0, 0.5});
  ASSERT_GT(ts.size(), 240000u);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_FALSE(first_initial_overlap(ts));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 10.0) << ts.size() << " triangles";
  RecordProperty("seconds", std::to_string(seconds));
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
