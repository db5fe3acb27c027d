// generate_grains and [[generate]] kind = "polygons" / "triangles": the measured size
// distribution against the requested one, no overlaps, every grain inside its region
// (rectangle, non-convex polygon), shapes as defined, reproducibility, refusals.
#include "scene_refusal.hpp"
#include "triangle_overlap.hpp"

#include "tridem/error.hpp"
#include "tridem/generate.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using test::expect_refused;
using test::kSceneHead;

double body_area(const GeneratedGrains& g, const BodySpec& b) {
  double a = 0;
  for (std::size_t k = b.first; k < b.first + b.count; ++k)
    a += 0.5 * test::twice_area(g.triangles[k].vertices);
  return a;
}
double size_of(const GeneratedGrains& g, const BodySpec& b) {
  return 2 * std::sqrt(body_area(g, b) / std::numbers::pi);
}

GrainSpec polygons_in_box(std::size_t count, double size) {
  GrainSpec s;
  s.region = {{0, 0}, {1, 1}};
  s.min_sides = 4;
  s.max_sides = 8;
  s.min_aspect = 1;
  s.max_aspect = 2;
  s.angularity = 0.5;
  s.sizes.min_size = s.sizes.max_size = size;
  s.count = count;
  s.seed = 7;
  return s;
}

void expect_bodies_cover(const GeneratedGrains& g) {
  std::size_t next = 0;
  for (const BodySpec& b : g.bodies) {
    ASSERT_EQ(b.first, next);
    ASSERT_GE(b.count, 1u);
    next += b.count;
  }
  EXPECT_EQ(next, g.triangles.size());
}

TEST(SceneGrains, PolygonsHaveTheirSidesAreaAndAreConvexBodies) {
  const GeneratedGrains g = generate_grains(polygons_in_box(300, 0.03));
  ASSERT_EQ(g.bodies.size(), 300u);
  expect_bodies_cover(g);
  std::size_t seen_min = 99, seen_max = 0;
  for (const BodySpec& b : g.bodies) {
    // A convex n-gon's constrained Delaunay triangulation has n - 2 triangles.
    const std::size_t sides = b.count + 2;
    seen_min = std::min(seen_min, sides);
    seen_max = std::max(seen_max, sides);
    EXPECT_NEAR(size_of(g, b), 0.03, 1e-12);  // size is the equal-area diameter
    for (std::size_t k = b.first; k < b.first + b.count; ++k)
      EXPECT_GT(test::twice_area(g.triangles[k].vertices), 0);  // counter-clockwise
  }
  EXPECT_EQ(seen_min, 4u);
  EXPECT_EQ(seen_max, 8u);
}

TEST(SceneGrains, RegularPolygonWithoutAngularityOrAspect) {
  GrainSpec s = polygons_in_box(20, 0.05);
  s.min_sides = s.max_sides = 6;
  s.max_aspect = 1;
  s.angularity = 0;
  const GeneratedGrains g = generate_grains(s);
  // A regular hexagon of area π d²/4 has circumradius R with (3√3/2) R² = π d²/4, and
  // every member vertex lies at R or at the other members' shared vertices.
  const double R = std::sqrt(std::numbers::pi * 0.05 * 0.05 / 4 / (1.5 * std::sqrt(3.0)));
  for (const BodySpec& b : g.bodies) {
    Vec2d c{};
    double a = 0;
    for (std::size_t k = b.first; k < b.first + b.count; ++k) {
      const auto& v = g.triangles[k].vertices;
      const double ak = 0.5 * test::twice_area(v);
      c += (v[0] + v[1] + v[2]) / 3.0 * ak;
      a += ak;
    }
    c = c / a;
    for (std::size_t k = b.first; k < b.first + b.count; ++k)
      for (const Vec2d& v : g.triangles[k].vertices) EXPECT_NEAR(norm(v - c), R, 1e-12);
  }
}

TEST(SceneGrains, SizeTableGivesTheRequestedMassFractions) {
  // 20000 triangles of three sizes. Number probabilities q_i ∝ f_i / d_i²; the measured
  // mass fraction of class i has, by the delta method on the multinomial counts,
  // variance (Σ_j g_j² q_j − (Σ_j g_j q_j)²) / N with g_j = (δ_ij m_i − F_i m_j) / M the
  // gradient of F_i = m_i q_i / M (m_j ∝ d_j², M = Σ m_j q_j). We accept 4 standard
  // deviations (a false failure once in ~16000 seeds; the seed is fixed, so this only
  // says the tolerance is not tuned to the draw).
  GrainSpec s;
  s.region = {{0, 0}, {4, 4}};
  s.sizes.classes = {{0.01, 0.2}, {0.02, 0.5}, {0.04, 0.3}};
  s.count = 20000;
  s.seed = 3;
  const GeneratedGrains g = generate_grains(s);
  ASSERT_EQ(g.bodies.size(), 20000u);
  std::array<double, 3> mass{}, counts{};
  for (const BodySpec& b : g.bodies) {
    ASSERT_EQ(b.count, 1u);
    const double d = size_of(g, b);
    int k = d < 0.015 ? 0 : d < 0.03 ? 1 : 2;
    EXPECT_NEAR(d, s.sizes.classes[static_cast<std::size_t>(k)].size, 1e-12);
    counts[static_cast<std::size_t>(k)] += 1;
    mass[static_cast<std::size_t>(k)] += body_area(g, b);
  }
  const double total = mass[0] + mass[1] + mass[2];
  std::array<double, 3> m{}, q{};
  double qsum = 0;
  for (std::size_t j = 0; j < 3; ++j) {
    m[j] = s.sizes.classes[j].size * s.sizes.classes[j].size;
    q[j] = s.sizes.classes[j].mass_fraction / m[j];
    qsum += q[j];
  }
  double M = 0;
  for (std::size_t j = 0; j < 3; ++j) M += m[j] * (q[j] /= qsum);
  for (std::size_t i = 0; i < 3; ++i) {
    const double F = m[i] * q[i] / M;
    double sum_g2q = 0, sum_gq = 0;
    for (std::size_t j = 0; j < 3; ++j) {
      const double gj = ((i == j ? m[i] : 0.0) - F * m[j]) / M;
      sum_g2q += gj * gj * q[j];
      sum_gq += gj * q[j];
    }
    const double sd = std::sqrt((sum_g2q - sum_gq * sum_gq) / 20000);
    EXPECT_NEAR(mass[i] / total, s.sizes.classes[i].mass_fraction, 4 * sd)
        << "class " << i << ", sd " << sd;
    // And the counts against their binomial spread.
    EXPECT_NEAR(counts[i] / 20000, q[i], 4 * std::sqrt(q[i] * (1 - q[i]) / 20000));
  }
}

TEST(SceneGrains, UniformRangeOfSizesPassesKolmogorovSmirnov) {
  // 5000 sizes uniform by number in [0.01, 0.03]: the Kolmogorov-Smirnov distance to the
  // uniform CDF must stay below 1.63/√N, its critical value at the 1% level.
  GrainSpec s;
  s.region = {{0, 0}, {3, 3}};
  s.min_sides = 3;
  s.max_sides = 6;
  s.sizes.min_size = 0.01;
  s.sizes.max_size = 0.03;
  s.count = 5000;
  s.seed = 11;
  const GeneratedGrains g = generate_grains(s);
  std::vector<double> d;
  for (const BodySpec& b : g.bodies) d.push_back(size_of(g, b));
  std::sort(d.begin(), d.end());
  double ks = 0;
  for (std::size_t k = 0; k < d.size(); ++k) {
    const double cdf = (d[k] - 0.01) / 0.02;
    ks = std::max({ks, std::abs(cdf - static_cast<double>(k) / 5000),
                   std::abs(cdf - static_cast<double>(k + 1) / 5000)});
  }
  EXPECT_LT(ks, 1.63 / std::sqrt(5000.0));
  EXPECT_GE(d.front(), 0.01 - 1e-12);
  EXPECT_LE(d.back(), 0.03 + 1e-12);
  // Largest first: ids follow placement order.
  EXPECT_GE(size_of(g, g.bodies.front()), size_of(g, g.bodies.back()));
}

TEST(SceneGrains, NoOverlapsAndInsideTheRectangleAtAHighPackingFraction) {
  GrainSpec s = polygons_in_box(0, 0.05);
  s.count = 0;
  s.packing_fraction = 0.4;  // random sequential addition of polygons jams near 0.5
  s.sizes.min_size = 0.03;
  s.sizes.max_size = 0.07;
  const GeneratedGrains g = generate_grains(s);
  double area = 0;
  for (const BodySpec& b : g.bodies) area += body_area(g, b);
  EXPECT_GE(area, 0.4);           // the target, reached
  EXPECT_LT(area, 0.4 + 0.0039);  // by at most the last grain (π 0.07² / 4)
  // All pairs of triangles, by the tests' own overlap test; members of one body share
  // edges and must not count as overlapping either.
  const auto o = test::find_overlap(g.triangles, 1e-12);
  EXPECT_FALSE(o) << "triangles " << o->first << " and " << o->second << " overlap";
  for (const TriangleSpec& t : g.triangles)
    for (const Vec2d& v : t.vertices) {
      EXPECT_GT(v.x, 0);
      EXPECT_LT(v.x, 1);
      EXPECT_GT(v.y, 0);
      EXPECT_LT(v.y, 1);
    }
}

bool inside_polygon(const std::vector<Vec2d>& poly, Vec2d p) {
  double winding = 0;  // sum of turned angles: 2π inside, 0 outside
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2d a = poly[i] - p, b = poly[(i + 1) % poly.size()] - p;
    winding += std::atan2(cross(a, b), dot(a, b));
  }
  return std::abs(winding) > std::numbers::pi;
}

TEST(SceneGrains, InsideANonConvexPolygonalRegion) {
  // A U: two arms joined at the bottom, with a notch 0.2 wide between them. Grains
  // straddling the notch would have all vertices inside and still cross its edges.
  const std::vector<Vec2d> u{{0, 0},     {1, 0},     {1, 1},   {0.6, 1},
                             {0.6, 0.3}, {0.4, 0.3}, {0.4, 1}, {0, 1}};
  GrainSpec s = polygons_in_box(0, 0.06);
  s.region = u;
  s.packing_fraction = 0.35;
  const GeneratedGrains g = generate_grains(s);
  EXPECT_GT(g.bodies.size(), 100u);
  for (const TriangleSpec& t : g.triangles)
    for (int k = 0; k < 3; ++k) {
      ASSERT_TRUE(inside_polygon(u, t.vertices[k]));
      for (std::size_t e = 0; e < u.size(); ++e)
        ASSERT_FALSE(test::properly_cross(t.vertices[k], t.vertices[(k + 1) % 3], u[e],
                                          u[(e + 1) % u.size()], 0));
    }
  EXPECT_FALSE(test::find_overlap(g.triangles, 1e-12));
}

TEST(SceneGrains, SameSeedSameGrainsOtherSeedOthers) {
  const GeneratedGrains a = generate_grains(polygons_in_box(100, 0.04));
  const GeneratedGrains b = generate_grains(polygons_in_box(100, 0.04));
  GrainSpec other = polygons_in_box(100, 0.04);
  other.seed = 8;
  const GeneratedGrains c = generate_grains(other);
  ASSERT_EQ(a.triangles.size(), b.triangles.size());
  for (std::size_t k = 0; k < a.triangles.size(); ++k)
    for (int v = 0; v < 3; ++v) {
      ASSERT_EQ(a.triangles[k].vertices[v].x, b.triangles[k].vertices[v].x);
      ASSERT_EQ(a.triangles[k].vertices[v].y, b.triangles[k].vertices[v].y);
    }
  EXPECT_NE(a.triangles[0].vertices[0].x, c.triangles[0].vertices[0].x);
}

Vec2d body_centroid(const GeneratedGrains& g, const BodySpec& b) {
  Vec2d sum{};
  for (std::size_t k = b.first; k < b.first + b.count; ++k)
    for (const Vec2d& v : g.triangles[k].vertices) sum = sum + v;
  return sum / static_cast<double>(3 * b.count);
}

// Mean id distance of the grains whose centroids lie within `reach` of each other.
double neighbour_id_distance(const GeneratedGrains& g, double reach) {
  double sum = 0;
  std::size_t pairs = 0;
  for (std::size_t a = 0; a < g.bodies.size(); ++a)
    for (std::size_t b = a + 1; b < g.bodies.size(); ++b)
      if (norm(body_centroid(g, g.bodies[a]) - body_centroid(g, g.bodies[b])) < reach) {
        sum += static_cast<double>(b - a);
        ++pairs;
      }
  return pairs > 0 ? sum / static_cast<double>(pairs) : 0;
}

TEST(SceneGrains, SpaceNumberingGivesTheSameGrainsWithNeighboursNumberedNearby) {
  GrainSpec s = polygons_in_box(0, 0.02);
  s.packing_fraction = 0.3;
  const GeneratedGrains placed = generate_grains(s);
  s.numbering = GrainNumbering::Space;
  const GeneratedGrains spaced = generate_grains(s);
  expect_bodies_cover(spaced);
  ASSERT_EQ(spaced.bodies.size(), placed.bodies.size());
  ASSERT_EQ(spaced.triangles.size(), placed.triangles.size());
  ASSERT_GT(placed.bodies.size(), 500u);
  // The same grains, member for member: each body of one numbering is a body of the other.
  auto key = [](const GeneratedGrains& g, const BodySpec& b) {
    std::vector<double> k;
    for (std::size_t t = b.first; t < b.first + b.count; ++t)
      for (const Vec2d& v : g.triangles[t].vertices) k.insert(k.end(), {v.x, v.y});
    return k;
  };
  std::vector<std::vector<double>> a, b;
  for (const BodySpec& body : placed.bodies) a.push_back(key(placed, body));
  for (const BodySpec& body : spaced.bodies) b.push_back(key(spaced, body));
  EXPECT_NE(a, b);  // renumbered
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  EXPECT_EQ(a, b);
  // Placed at random, touching grains' ids are a third of the count apart; along the curve
  // a few rows of grains.
  const double before = neighbour_id_distance(placed, 0.05);
  const double after = neighbour_id_distance(spaced, 0.05);
  EXPECT_GT(before, 0.2 * static_cast<double>(placed.bodies.size()));
  EXPECT_LT(after, 0.15 * before);  // 26 against 320 here
}

TEST(SceneGrains, TooManyGrainsForTheRegionIsRefusedSayingWhatWasReached) {
  GrainSpec s = polygons_in_box(0, 0.1);
  s.packing_fraction = 0.8;  // beyond what random sequential addition can reach
  s.max_attempts = 200;
  try {
    generate_grains(s);
    FAIL() << "accepted";
  } catch (const SceneError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("placed "), std::string::npos) << m;
    EXPECT_NE(m.find("packing fraction 0."), std::string::npos) << m;
    EXPECT_NE(m.find("0.8 asked for"), std::string::npos) << m;
    EXPECT_NE(m.find("200 random positions (max_attempts)"), std::string::npos) << m;
  }
}

std::string with_grains(std::string_view body) {
  return std::string(kSceneHead) + "[[generate]]\nmaterial = \"m\"\n" + std::string(body);
}

TEST(SceneGrains, SceneFileNumbersGeneratedBodiesAfterExplicitOnes) {
  const std::string text = std::string(kSceneHead) +
                           "[[triangle]]\nmaterial = \"m\"\nvertices = [[5, 5], [6, 5], [5, 6]]\n"
                           "[[generate]]\nkind = \"polygons\"\nmaterial = \"m\"\n"
                           "region = [[0, 0], [1, 0], [1, 1], [0, 1]]\nsides = [5, 7]\n"
                           "aspect_ratio = [1, 1.5]\nangularity = 0.3\n"
                           "sizes = [0.05, 0.1]\nmass_fractions = [0.4, 0.6]\n"
                           "packing_fraction = 0.3\nseed = 5\nvelocity = [0, -1]\n"
                           "[[generate]]\nkind = \"triangles\"\nmaterial = \"m\"\n"
                           "region = [[2, 0], [3, 1]]\nsize = [0.05, 0.08]\ncount = 10\n";
  const Scene s = parse_scene(text, "s.toml");
  ASSERT_TRUE(s.has_bodies());
  EXPECT_EQ(s.bodies.front().first, 0u);
  EXPECT_EQ(s.bodies.front().count, 1u);  // the [[triangle]], body id 0
  std::size_t next = 0, polygons = 0;
  for (const BodySpec& b : s.bodies) {
    ASSERT_EQ(b.first, next);
    next += b.count;
    polygons += b.count >= 3;
  }
  EXPECT_EQ(next, s.triangles.size());
  EXPECT_GT(polygons, 10u);
  EXPECT_EQ(s.bodies[1].velocity.y, -1);
  // The ten triangles come last, one body each.
  for (std::size_t k = s.bodies.size() - 10; k < s.bodies.size(); ++k)
    EXPECT_EQ(s.bodies[k].count, 1u);
}

TEST(SceneGrains, SceneFileChoosesTheNumbering) {
  const std::string grains = "kind = \"triangles\"\nregion = [[0, 0], [1, 1]]\nsize = 0.05\n"
                             "count = 60\nseed = 4\n";
  const Scene placed = parse_scene(with_grains(grains), "s.toml");
  const Scene spaced = parse_scene(with_grains(grains + "numbering = \"space\"\n"), "s.toml");
  const Scene same = parse_scene(with_grains(grains + "numbering = \"placement\"\n"), "s.toml");
  ASSERT_EQ(spaced.triangles.size(), placed.triangles.size());
  auto first_vertex = [](const Scene& s, std::size_t i) { return s.triangles[i].vertices[0].x; };
  bool differs = false;
  for (std::size_t i = 0; i < placed.triangles.size(); ++i) {
    differs |= first_vertex(spaced, i) != first_vertex(placed, i);
    EXPECT_EQ(first_vertex(same, i), first_vertex(placed, i));
  }
  EXPECT_TRUE(differs);
  expect_refused(with_grains(grains + "numbering = \"random\"\n"),
                 {"key 'numbering'", "placement", "space"});
}

TEST(SceneGrains, TrianglesAloneMakeNoBodies) {
  const Scene s = parse_scene(with_grains("kind = \"triangles\"\nregion = [[0, 0], [1, 1]]\n"
                                          "size = 0.05\ncount = 50\n"),
                              "s.toml");
  EXPECT_EQ(s.triangles.size(), 50u);
  EXPECT_TRUE(s.bodies.empty());  // as every scene of lone triangles
}

TEST(SceneGrains, RefusalsNameTheKey) {
  const std::string region = "region = [[0, 0], [1, 1]]\n";
  expect_refused(with_grains("kind = \"polygons\"\n" + region + "size = 0.1\ncount = 5\n"),
                 {"bad.toml:7:1", "[[generate]] #1", "missing required key 'sides'"});
  expect_refused(
      with_grains("kind = \"triangles\"\n" + region + "sides = 4\nsize = 0.1\ncount = 5\n"),
      {"key 'sides'", "applies only to kind = \"polygons\""});
  expect_refused(
      with_grains("kind = \"polygons\"\n" + region + "sides = [3, 80]\nsize = 0.1\ncount = 5\n"),
      {"key 'sides'", "within [3, 64]"});
  expect_refused(
      with_grains("kind = \"polygons\"\n" + region + "sides = [6, 4]\nsize = 0.1\ncount = 5\n"),
      {"key 'sides'", "min must not exceed max"});
  expect_refused(with_grains("kind = \"triangles\"\n" + region +
                             "aspect_ratio = 0.5\nsize = 0.1\ncount = 5\n"),
                 {"key 'aspect_ratio'", ">= 1"});
  expect_refused(
      with_grains("kind = \"triangles\"\n" + region + "angularity = 1\nsize = 0.1\ncount = 5\n"),
      {"key 'angularity'", "[0, 1)"});
  expect_refused(with_grains("kind = \"triangles\"\n" + region +
                             "sizes = [0.1, 0.2]\nmass_fractions = [0.5, 0.4]\ncount = 5\n"),
                 {"key 'mass_fractions'", "must sum to 1, they sum to 0.9"});
  expect_refused(with_grains("kind = \"triangles\"\n" + region +
                             "sizes = [0.1, 0.2]\nmass_fractions = [1]\ncount = 5\n"),
                 {"key 'mass_fractions'", "has 1 values for 2 sizes"});
  expect_refused(with_grains("kind = \"triangles\"\n" + region + "size = 0.1\n"),
                 {"missing how many grains"});
  expect_refused(with_grains("kind = \"triangles\"\n" + region +
                             "size = 0.1\ncount = 5\npacking_fraction = 0.1\n"),
                 {"key 'packing_fraction'", "not both"});
  expect_refused(with_grains("kind = \"triangles\"\nregion = [[0, 0], [1, 1], [1, 0], [0, 1]]\n"
                             "size = 0.1\ncount = 5\n"),
                 {"key 'region'", "intersects itself"});
  expect_refused(
      with_grains("kind = \"triangles\"\n" + region + "size = 0.1\ncount = 5\ngap = 0.1\n"),
      {"unknown key 'gap'"});
  expect_refused(
      with_grains("kind = \"triangles\"\n" + region + "size = 2\ncount = 1\nmax_attempts = 50\n"),
      {"key 'count'", "placed 0 of 1 grains", "50 random positions"});
  expect_refused(
      with_grains("kind = \"triangles\"\n" + region + "size = 1e-6\npacking_fraction = 0.5\n"),
      {"key 'packing_fraction'", "more than the limit"});
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
