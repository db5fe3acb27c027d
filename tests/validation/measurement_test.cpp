// The measurements of tridem/measurements.hpp against known answers (issue 15): the
// coordination, fabric and overlaps of a lattice whose contacts are known exactly, the
// packing fraction of a tiling, rattlers removed recursively, bodies counted as one grain,
// and the Love-Weber stress of a packing in static equilibrium against the forces of the
// walls that hold it.
#include "support/body_scenes.hpp"
#include "support/lattice_scenes.hpp"
#include "support/scene_builder.hpp"
#include "tridem/measurements.hpp"
#include "tridem/standard_scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <set>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

constexpr double kSqrt3 = 1.7320508075688772;

/// Rows of upward equilateral triangles of side a, `columns` in a row at pitch a − d (the
/// right vertex of each inside its right neighbour's base corner: a small equilateral
/// overlap of side d), rows at pitch h − e (each apex e into the base of the one above).
/// Every contact is known: R(C − 1) horizontal ones of depth φ = 3d/(2a), C(R − 1)
/// vertical ones of depth φ = 3e/h, h = a√3/2 (the apex is e/h of a height inside, so
/// φ = 3e/h; along the right edge inside the neighbour φ peaks where the distances to
/// its base and left edge are equal, (d/2)·(√3/2), i.e. φ = 3·(d√3/4)/h = 3d/(2a)).
struct RowLattice {
  double a = 0.1, d = 0.004, e = 0.002;
  int columns = 6, rows = 5;
  double h() const { return a * kSqrt3 / 2; }
  Vec2d corner(int k, int j) const { return {k * (a - d), j * (h() - e)}; }
  TriangleSpec at(int k, int j) const {
    const Vec2d c = corner(k, j);
    return test::triangle(c, c + Vec2d{a, 0}, c + Vec2d{a / 2, h()});
  }
  Scene scene() const {
    Scene s = test::empty_scene(1e7, 2000, 0.3, 0);
    for (int j = 0; j < rows; ++j)
      for (int k = 0; k < columns; ++k) s.triangles.push_back(at(k, j));
    return s;
  }
  int horizontal() const { return rows * (columns - 1); }
  int vertical() const { return columns * (rows - 1); }
};

/// A lattice of equilateral triangles (side a, each shrunk to `scale` about its centroid:
/// packing fraction scale²) filling a cell periodic in x and y of 4 x 2 lattice periods
/// (0.4 m x 0.346 m, 32 triangles), moved by (0.3a, 0.2h) so that the first triangle of
/// each row and the top row lie across the cell's sides; each triangle's centroid is in
/// the cell. With `shear_rate`, Lees-Edwards boundaries and the grains started on the
/// shear profile, so that the images above and below are shifted.
Scene periodic_lattice(double scale, double shear_rate = 0) {
  const double a = 0.1, h = a * kSqrt3 / 2;
  const int periods_x = 4, row_pairs = 2;
  Scene s = test::empty_scene(1e7, 2000, 0.3, 0);
  s.simulation.periodic.x = PeriodicRange{0, periods_x * a};
  s.simulation.periodic.y = PeriodicRange{0, 2 * row_pairs * h};
  s.simulation.periodic.shear_rate = shear_rate;
  for (int j = 0; j < 2 * row_pairs; ++j)
    for (int i = -1; i < 2 * periods_x - 1; ++i) {  // i = j + k: x0 = i·a/2
      TriangleSpec t = test::lattice_triangle(i - j, j, a, scale);
      for (Vec2d& v : t.vertices) v += Vec2d{0.3 * a, 0.2 * h};
      const Vec2d c = (t.vertices[0] + t.vertices[1] + t.vertices[2]) / 3.0;
      t.velocity = {shear_rate * (c.y - row_pairs * h), 0};
      s.triangles.push_back(t);
    }
  return s;
}

// A [[measure]] over a periodic cell counts each grain's area once: the parts of grains
// across a side are in the cell through their images (the packing fraction of the cell
// was 3-4 % low when only the parts inside were counted).
TEST(Measurements, PeriodicCellPackingFractionCountsTheImages) {
  const double scale = 0.9;
  const Scene s = periodic_lattice(scale);
  const MeasureRegion cell{{0, 0}, {s.simulation.periodic.x->hi, s.simulation.periodic.y->hi}};
  Snapshot snap = test::run_to(s, Backend::Cpu, 0);
  bool across = false;
  for (std::size_t i = 0; i < snap.size(); ++i)
    for (const double x : {snap.x1[i], snap.x2[i], snap.x3[i]}) across = across || x < 0;
  ASSERT_TRUE(across) << "some grain must lie across the cell's left side";
  EXPECT_NEAR(measure_region(snap, cell).packing_fraction, scale * scale, 1e-12);
  // A region of the cell's lower half holds half the grains' area: the lattice is periodic
  // along y with half the cell's height, so its half is one whole period of the lattice.
  const MeasureRegion lower{{0, 0}, {cell.hi.x, 0.5 * cell.hi.y}};
  EXPECT_NEAR(measure_region(snap, lower).packing_fraction, scale * scale, 1e-12);
  // Sheared (Lees-Edwards): after 2000 steps the images above and below are shifted by
  // γ̇·Ly·t; the cell holds every grain's area once whatever the grains did.
  const Scene sheared = periodic_lattice(scale, 5.0);
  snap = test::run_to(sheared, Backend::Cpu, 2000);
  const double shift = std::fmod(5.0 * cell.hi.y * snap.time, cell.hi.x);
  ASSERT_GT(shift, 0.01);
  EXPECT_NEAR(measure_region(snap, cell).packing_fraction, scale * scale, 1e-12)
      << "shift " << shift << " m";
}

/// The snapshot after one step: its contacts are those of the scene as built.
Snapshot first_step(const Scene& scene) { return test::run_to(scene, Backend::Cpu, 1); }

TEST(Measurements, LatticeCoordinationFabricAndOverlapAreExact) {
  const RowLattice lattice;
  const Snapshot s = first_step(lattice.scene());
  const int contacts = lattice.horizontal() + lattice.vertical();  // 25 + 24
  ASSERT_EQ(s.contacts.size(), static_cast<std::size_t>(contacts));
  const Measurement m = measure_region(s, std::nullopt);
  EXPECT_EQ(m.particles, 30);
  EXPECT_EQ(m.contacts, contacts);
  EXPECT_EQ(m.rattlers, 0);
  EXPECT_DOUBLE_EQ(m.coordination, 2.0 * contacts / 30);  // 3.2667
  EXPECT_DOUBLE_EQ(m.mechanical_coordination, m.coordination);
  // Horizontal contacts have normal (±1, 0), vertical ones (0, ±1).
  EXPECT_NEAR(m.fabric_xx, double(lattice.horizontal()) / contacts, 1e-12);
  EXPECT_NEAR(m.fabric_yy, double(lattice.vertical()) / contacts, 1e-12);
  EXPECT_NEAR(m.fabric_xy, 0, 1e-12);
  EXPECT_NEAR(m.fabric_xx + m.fabric_yy, 1, 1e-15);
  const double phi_h = 3 * lattice.d / (2 * lattice.a), phi_v = 3 * lattice.e / lattice.h();
  EXPECT_NEAR(m.max_overlap, std::max(phi_h, phi_v), 1e-12);
  EXPECT_NEAR(m.mean_overlap,
              (lattice.horizontal() * phi_h + lattice.vertical() * phi_v) / contacts, 1e-12);

  // A region around the inner grains by their centroids: each has 4 contacts.
  const Vec2d lo = lattice.corner(1, 1), hi = lattice.corner(5, 4);  // columns 1-4, rows 1-3
  const Measurement inner = measure_region(s, MeasureRegion{lo, hi});
  EXPECT_EQ(inner.particles, 12);
  EXPECT_EQ(inner.coordination, 4.0);
  EXPECT_EQ(inner.mechanical_coordination, 4.0);
  // 12 grains × 4 contacts, the 10 + 9 between two of them counted once.
  EXPECT_EQ(inner.contacts, 12 * 4 - (3 * 3 + 4 * 2));
  EXPECT_DOUBLE_EQ(inner.area, (hi.x - lo.x) * (hi.y - lo.y));

  // Per grain: a corner has 2 contacts, an inner grain 4.
  const GrainStress g = grain_stress(s);
  EXPECT_EQ(g.coordination[0], 2);
  EXPECT_EQ(g.coordination[static_cast<std::size_t>(2 * lattice.columns + 2)], 4);
}

/// The grains' stress and coordination as the serial definition reads: every contact in
/// record order adds its moment to both grains, and a grain's coordination is the number of
/// distinct grains it touches.
GrainStress serial_grain_stress(const Snapshot& s) {
  const std::size_t n = s.body_count();
  std::vector<double> xx(n), xy(n), yx(n), yy(n), area(n);
  std::vector<std::set<std::int64_t>> touching(n);
  std::vector<Vec2d> centroid(n);
  for (std::size_t b = 0; b < n; ++b)
    centroid[b] = s.member_body.empty() ? Vec2d{s.x[b], s.y[b]} : Vec2d{s.body_x[b], s.body_y[b]};
  for (std::size_t i = 0; i < s.size(); ++i)
    area[static_cast<std::size_t>(s.body_of(i))] +=
        0.5 * std::abs((s.x2[i] - s.x1[i]) * (s.y3[i] - s.y1[i]) -
                       (s.x3[i] - s.x1[i]) * (s.y2[i] - s.y1[i]));
  for (const ContactRecord& c : s.contacts) {
    const auto a = static_cast<std::size_t>(s.body_of(static_cast<std::size_t>(c.i)));
    const auto b = static_cast<std::size_t>(s.body_of(static_cast<std::size_t>(c.j)));
    if (a == b) continue;
    touching[a].insert(static_cast<std::int64_t>(b));
    touching[b].insert(static_cast<std::int64_t>(a));
    for (const auto& [g, sign] : {std::pair{a, 1.0}, std::pair{b, -1.0}}) {
      const double sx = sign < 0 ? c.image_dx : 0.0, sy = sign < 0 ? c.image_dy : 0.0;
      const double lx = c.px - (centroid[g].x + sx), ly = c.py - (centroid[g].y + sy);
      const double fx = sign * c.fx, fy = sign * c.fy;
      xx[g] += fx * lx;
      xy[g] += fx * ly;
      yx[g] += fy * lx;
      yy[g] += fy * ly;
    }
  }
  GrainStress out;
  for (std::size_t g = 0; g < n; ++g) {
    const double scale = area[g] > 0 ? -1.0 / area[g] : 0.0;
    out.sxx.push_back(scale * xx[g]);
    out.sxy.push_back(scale * xy[g]);
    out.syx.push_back(scale * yx[g]);
    out.syy.push_back(scale * yy[g]);
    out.coordination.push_back(static_cast<std::int32_t>(touching[g].size()));
  }
  return out;
}

// grain_stress sums each grain on the OpenMP threads from a list of its contacts: the same
// sums in the same order as the serial definition, bit for bit, on a dense pile (6 contacts
// per triangle, on more than one thread where there are cores) and on bodies of several
// triangles.
TEST(Measurements, GrainStressIsTheSerialSumBitForBit) {
  Scene bodies = test::empty_scene(1e7, 2000, 0.3, 0);
  const double b = 0.1;
  for (int k = 0; k < 3; ++k) {
    const std::size_t first = bodies.triangles.size();
    const Vec2d p{k * (b - 0.002), 0};
    bodies.triangles.push_back(test::triangle(p, p + Vec2d{b, 0}, p + Vec2d{b, b}));
    bodies.triangles.push_back(test::triangle(p, p + Vec2d{b, b}, p + Vec2d{0, b}));
    test::add_body(bodies, first);
  }
  Scene pile = dense_pile(20000);
  pile.simulation.backend = Backend::Cpu;
  for (const Scene* scene : {&pile, &bodies}) {
    const Snapshot s = test::run_to(*scene, Backend::Cpu, 5);
    ASSERT_FALSE(s.contacts.empty());
    const GrainStress got = grain_stress(s), want = serial_grain_stress(s);
    EXPECT_EQ(got.sxx, want.sxx);
    EXPECT_EQ(got.sxy, want.sxy);
    EXPECT_EQ(got.syx, want.syx);
    EXPECT_EQ(got.syy, want.syy);
    EXPECT_EQ(got.coordination, want.coordination);
  }
}

TEST(Measurements, RattlersAreRemovedRecursively) {
  RowLattice lattice;
  Scene scene = lattice.scene();
  // Two more triangles at the end of row 0: the last one touches only the first, which
  // touches only the lattice once the last is gone.
  scene.triangles.push_back(lattice.at(lattice.columns, 0));
  scene.triangles.push_back(lattice.at(lattice.columns + 1, 0));
  // And one far away, touching nothing.
  scene.triangles.push_back(test::triangle({5, 5}, {5.1, 5}, {5.05, 5.08}));
  const Snapshot s = first_step(scene);
  const int contacts = lattice.horizontal() + lattice.vertical() + 2;
  ASSERT_EQ(s.contacts.size(), static_cast<std::size_t>(contacts));
  const std::vector<bool> rattler = find_rattlers(s);
  EXPECT_EQ(std::count(rattler.begin(), rattler.end(), true), 3);
  EXPECT_TRUE(rattler[30] && rattler[31] && rattler[32]);
  const Measurement m = measure_region(s, std::nullopt);
  EXPECT_EQ(m.particles, 33);
  EXPECT_EQ(m.rattlers, 3);
  EXPECT_DOUBLE_EQ(m.coordination, 2.0 * contacts / 33);
  EXPECT_DOUBLE_EQ(m.mechanical_coordination, 2.0 * (contacts - 2) / 30);
}

TEST(Measurements, PackingFractionOfATilingIsExact) {
  // Squares of side b, each cut by a diagonal into two triangles, tiling [0, 8b] × [0, 5b]
  // edge to edge (no overlap); a fixed wall below, which does not count.
  const double b = 0.05;
  Scene scene = test::empty_scene();
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 8; ++i) {
      const Vec2d p{i * b, j * b};
      scene.triangles.push_back(test::triangle(p, p + Vec2d{b, 0}, p + Vec2d{b, b}));
      scene.triangles.push_back(test::triangle(p, p + Vec2d{b, b}, p + Vec2d{0, b}));
    }
  scene.triangles.push_back(test::floor_triangle(0, 8 * b, -0.01));
  Snapshot s;
  make_solver(scene, SolverConfig{})->snapshot(s, true);
  // Inside the tiling, whatever the cut: 1.
  for (const MeasureRegion r :
       {MeasureRegion{{0, 0}, {8 * b, 5 * b}}, MeasureRegion{{0.0123, 0.0371}, {0.2897, 0.1999}},
        MeasureRegion{{0.31, 0.001}, {0.3333, 0.249}}}) {
    const Measurement m = measure_region(s, r);
    EXPECT_NEAR(m.packing_fraction, 1, 1e-13) << r.lo.x << " " << r.lo.y;
  }
  // Half outside on the right and above: the tiling's part of the region over its area.
  const MeasureRegion half{{0.3, 0.2}, {0.5, 0.3}};  // tiling up to x = 0.4, y = 0.25
  EXPECT_NEAR(measure_region(s, half).packing_fraction, (0.1 * 0.05) / (0.2 * 0.1), 1e-13);
  // The whole domain: the free triangles' bounding box, which the tiling fills.
  const Measurement all = measure_region(s, std::nullopt);
  EXPECT_NEAR(all.area, 8 * b * 5 * b, 1e-15);
  EXPECT_NEAR(all.packing_fraction, 1, 1e-13);
  EXPECT_EQ(all.particles, 80);
}

TEST(Measurements, ABodyIsOneGrainWithOneContactPerNeighbour) {
  // Three square bodies of two triangles side by side, each overlapping the next by 1 %;
  // the squares' shared edges meet triangles of both halves, so a neighbour may touch
  // through more than one pair of triangles: still one contact.
  Scene scene = test::empty_scene(1e7, 2000, 0, 0);
  const double b = 0.1, step = 0.099;
  for (int k = 0; k < 3; ++k) {
    const std::size_t first = scene.triangles.size();
    const Vec2d p{k * step, 0};
    scene.triangles.push_back(test::triangle(p, p + Vec2d{b, 0}, p + Vec2d{b, b}));
    scene.triangles.push_back(test::triangle(p, p + Vec2d{b, b}, p + Vec2d{0, b}));
    test::add_body(scene, first);
  }
  const Snapshot s = first_step(scene);
  ASSERT_GE(s.contacts.size(), 2u);
  const Measurement m = measure_region(s, std::nullopt);
  EXPECT_EQ(m.particles, 3);
  EXPECT_EQ(m.contacts, 2);
  EXPECT_DOUBLE_EQ(m.coordination, 4.0 / 3);
  const GrainStress g = grain_stress(s);
  ASSERT_EQ(g.coordination.size(), 3u);
  EXPECT_EQ(g.coordination, (std::vector<std::int32_t>{1, 2, 1}));
  // The region's stress is the grains' own, weighted by their areas.
  const double area = b * b;
  EXPECT_NEAR(m.sxx * m.area, area * (g.sxx[0] + g.sxx[1] + g.sxx[2]),
              1e-9 * std::abs(m.sxx * m.area));
  EXPECT_GT(g.sxx[1], 0) << "the middle square is compressed along x";
  // The normals are along x, up to the small corner contacts: the fabric is nearly all xx.
  EXPECT_NEAR(m.fabric_xx, 1, 1e-3);
}

/// An equilateral triangle (side 0.1 m) pressed e = 1 mm into a fixed floor, moving along
/// it at `speed`; friction 0.3, no damping, no gravity.
Scene on_floor(double speed) {
  Scene scene = test::empty_scene(1e7, 2000, 0.3, 0);
  scene.triangles.push_back(test::floor_triangle(-1, 2, 0));
  const double a = 0.1, e = 0.001;
  scene.triangles.push_back(
      test::triangle({0, -e}, {a, -e}, {a / 2, a * kSqrt3 / 2 - e}, {speed, 0}));
  return scene;
}

TEST(Measurements, TheContactNetworkSplitsNormalAndTangentialAndSaysWhenItSlides) {
  {
    const Snapshot s = first_step(on_floor(0));
    ASSERT_EQ(s.contacts.size(), 1u);
    const ContactRecord& c = s.contacts[0];
    // The normal from i into j: straight down into the floor, or up out of it.
    const double towards_j =
        s.y[static_cast<std::size_t>(c.j)] - s.y[static_cast<std::size_t>(c.i)];
    EXPECT_NEAR(c.nx, 0, 1e-12);
    EXPECT_NEAR(c.ny, towards_j > 0 ? 1 : -1, 1e-12);
    EXPECT_GT(c.normal_force(), 0) << "the floor pushes the triangle up";
    // The floor's top edge runs e inside the triangle, parallel to its base: φ = 3e/h.
    EXPECT_NEAR(c.depth, 3 * 0.001 / (0.1 * kSqrt3 / 2), 1e-12);
    EXPECT_FALSE(c.sliding) << "at rest";
    EXPECT_EQ(c.tangential_force(), 0);
  }
  // Moving at 20 m/s: the friction spring stretches until it reaches the Coulomb cap μ·fn,
  // then the contact slides at the cap, against the motion.
  const auto solver = make_solver(on_floor(20), SolverConfig{});
  Snapshot s;
  int sticking = 0, sliding = 0;
  for (int step = 1; step <= 200 && sliding < 3; ++step) {
    solver->advance(1);
    solver->snapshot(s, true);
    if (s.contacts.empty()) break;
    const ContactRecord& c = s.contacts[0];
    const double on_triangle = c.i == 1 ? 1 : -1;
    EXPECT_LT(on_triangle * c.fx, 0) << "friction opposes the motion, step " << step;
    if (c.sliding) {
      ++sliding;
      EXPECT_NEAR(std::abs(c.tangential_force()), 0.3 * c.normal_force(), 1e-9 * c.normal_force());
    } else {
      EXPECT_EQ(sliding, 0) << "sticks again at step " << step;
      ++sticking;
      EXPECT_LT(std::abs(c.tangential_force()), 0.3 * c.normal_force());
    }
  }
  EXPECT_GT(sticking, 0);
  EXPECT_EQ(sliding, 3) << "the contact reached the cap while it lasted";
}

/// Four fixed walls whose faces are the sides of the box [0, W] × [0, H] (each a triangle
/// with its face on one side, meeting the next only at a corner), in the order Left,
/// Right, Bottom, Top.
enum Wall { Left, Right, Bottom, Top };
void add_box_walls(Scene& s, double w, double h) {
  s.triangles.push_back(test::triangle({0, h}, {-h / 2, h / 2}, {0, 0}, {}, Motion::Fixed));
  s.triangles.push_back(test::triangle({w, 0}, {w + h / 2, h / 2}, {w, h}, {}, Motion::Fixed));
  s.triangles.push_back(test::triangle({0, 0}, {w / 2, -w / 2}, {w, 0}, {}, Motion::Fixed));
  s.triangles.push_back(test::triangle({w, h}, {w / 2, h + w / 2}, {0, h}, {}, Motion::Fixed));
}

void enlarge(TriangleSpec& t, double scale) {
  const Vec2d c = (t.vertices[0] + t.vertices[1] + t.vertices[2]) / 3.0;
  for (Vec2d& v : t.vertices) v = c + (v - c) * scale;
}

/// A packing in the box, no gravity, damped (material damping and Cundall's local
/// damping) until static.
Snapshot settled(Scene s) {
  s.materials[0].damping = 0.5;
  s.simulation.local_damping = 0.3;
  return test::run_to(s, Backend::Cpu, 20000);
}

/// What the walls hold: the force of the grains on each (the walls' contact force).
struct WallLoads {
  double left, right, bottom, top;
  explicit WallLoads(const Snapshot& s)
      : left(-s.fx[Left]), right(s.fx[Right]), bottom(-s.fy[Bottom]), top(s.fy[Top]) {}
};

/// The largest net force on a grain (walls excluded): zero in static equilibrium.
double largest_net_force(const Snapshot& s) {
  double largest = 0;
  for (std::size_t i = 4; i < s.size(); ++i)
    largest = std::max(largest, std::hypot(s.fx[i], s.fy[i]));
  return largest;
}

TEST(Measurements, StressOfAStaticPackingEqualsTheWallForcesOverTheirLengths) {
  // Squares of side b, 8 × 6, each cut by its diagonal into two right triangles enlarged
  // by 1 % about their centroids: the packing presses its faces flat on the walls, whose
  // loads are then normal to them (a vertex pressed into a face would also load it along
  // the face: see the next test), so σxx = (wall force)/H and σyy = (wall force)/W.
  const double b = 0.1, w = 8 * b, h = 6 * b;
  Scene scene = test::empty_scene(1e7, 2000, 0, 0);
  add_box_walls(scene, w, h);
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 8; ++i) {
      const Vec2d p{i * b, j * b};
      for (TriangleSpec t : {test::triangle(p, p + Vec2d{b, 0}, p + Vec2d{b, b}),
                             test::triangle(p, p + Vec2d{b, b}, p + Vec2d{0, b})}) {
        enlarge(t, 1.01);
        scene.triangles.push_back(t);
      }
    }
  const Snapshot s = settled(scene);
  const WallLoads wall(s);
  ASSERT_GT(wall.left, 0);
  ASSERT_GT(wall.bottom, 0);
  EXPECT_NEAR(wall.left, wall.right, 1e-3 * wall.left);
  EXPECT_NEAR(wall.bottom, wall.top, 1e-3 * wall.bottom);
  EXPECT_LT(largest_net_force(s), 1e-4 * wall.left) << "static: the grains' net forces vanish";

  const Measurement m = measure_region(s, MeasureRegion{{0, 0}, {w, h}});
  EXPECT_EQ(m.particles, 96);
  const double sxx_walls = 0.5 * (wall.left + wall.right) / h;
  const double syy_walls = 0.5 * (wall.bottom + wall.top) / w;
  EXPECT_NEAR(m.sxx, sxx_walls, 0.01 * sxx_walls);
  EXPECT_NEAR(m.syy, syy_walls, 0.01 * syy_walls);
  EXPECT_NEAR(m.sxy, 0, 0.01 * m.pressure);
  EXPECT_NEAR(m.syx, 0, 0.01 * m.pressure);
  EXPECT_NEAR(m.pressure, 0.5 * (sxx_walls + syy_walls), 0.01 * m.pressure);
  EXPECT_NEAR(m.packing_fraction, 1, 0.05) << "a tiling, enlarged and pressed back";
  std::printf("net force %.3g N/m; sxx %.6g vs walls %.6g (%.2g), syy %.6g vs walls %.6g "
              "(%.2g), sxy %.3g, syx %.3g\n",
              largest_net_force(s), m.sxx, sxx_walls, m.sxx / sxx_walls - 1, m.syy, syy_walls,
              m.syy / syy_walls - 1, m.sxy, m.syx);
}

TEST(Measurements, StressOfAStaticPackingEqualsItsBoundaryTractions) {
  // A triangular lattice (6 rows of 14 triangles, enlarged by 1 %) pressed into the box:
  // the rows' ends press vertices into the side walls, which the potential force loads
  // along the wall too, frictionless as it is. What holds exactly in static equilibrium
  // without gravity is σ·A = −Σ f ⊗ x over the walls' contacts (f on the grain, at x).
  constexpr double a = 0.1, th = a * kSqrt3 / 2;
  constexpr int half_columns = 7, rows = 6;
  const double w = (half_columns + 0.5) * a, h = rows * th;
  Scene scene = test::empty_scene(1e7, 2000, 0, 0);
  add_box_walls(scene, w, h);
  for (int j = 0; j < rows; ++j)
    for (int k = 0; k < 2 * half_columns; ++k) {
      // Triangle k of row j starts at x = k·a/2: up when k + j is even, else down.
      const double x0 = k * a / 2, y0 = j * th;
      TriangleSpec t = (k + j) % 2 == 0
                           ? test::triangle({x0, y0}, {x0 + a, y0}, {x0 + a / 2, y0 + th})
                           : test::triangle({x0, y0 + th}, {x0 + a / 2, y0}, {x0 + a, y0 + th});
      enlarge(t, 1.01);
      scene.triangles.push_back(t);
    }
  const Snapshot s = settled(scene);
  const WallLoads wall(s);
  ASSERT_GT(wall.left, 0);
  EXPECT_LT(largest_net_force(s), 1e-4 * wall.left) << "static: the grains' net forces vanish";
  double txx = 0, txy = 0, tyx = 0, tyy = 0;  // −Σ f ⊗ x over the walls' contacts
  for (const ContactRecord& c : s.contacts) {
    const bool i_wall = c.i < 4, j_wall = c.j < 4;
    if (i_wall == j_wall) continue;
    const double sign = i_wall ? -1 : 1;  // the force on the grain
    txx -= sign * c.fx * c.px;
    txy -= sign * c.fx * c.py;
    tyx -= sign * c.fy * c.px;
    tyy -= sign * c.fy * c.py;
  }
  const Measurement m = measure_region(s, MeasureRegion{{0, 0}, {w, h}});
  EXPECT_EQ(m.particles, 2 * half_columns * rows);
  const double area = w * h, tolerance = 1e-3 * m.pressure;
  EXPECT_NEAR(m.sxx, txx / area, tolerance);
  EXPECT_NEAR(m.sxy, txy / area, tolerance);
  EXPECT_NEAR(m.syx, tyx / area, tolerance);
  EXPECT_NEAR(m.syy, tyy / area, tolerance);
  // The side walls' normal forces alone still give σxx; σyy differs from the floor's and
  // lid's by what the side walls carry along themselves.
  EXPECT_NEAR(m.sxx, 0.5 * (wall.left + wall.right) / h, 0.01 * m.sxx);
  // The whole domain (no region) measures the same grains, over their bounding box.
  const Measurement all = measure_region(s, std::nullopt);
  EXPECT_EQ(all.particles, m.particles);
  EXPECT_NEAR(all.sxx * all.area, m.sxx * m.area, 1e-9 * m.sxx * m.area);
  std::printf("net force %.3g N/m; sxx %.6g vs tractions %.6g, syy %.6g vs %.6g (floor and lid "
              "alone: %.6g), sxy %.4g vs %.4g\n",
              largest_net_force(s), m.sxx, txx / area, m.syy, tyy / area,
              0.5 * (wall.bottom + wall.top) / w, m.sxy, txy / area);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
