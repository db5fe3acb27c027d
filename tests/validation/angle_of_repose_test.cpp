// A heap of pentagons stands steeper than a heap of discs (12-gons of 12 triangles) at the
// same friction: angular grains interlock where round ones roll, the trend of the 2D
// polygon DEM literature. Both heaps are made alike (docs/validation-bodies.md): a column
// of grains between two walls on a rough platform; the walls rise and the column slumps,
// the grains beyond the platform's edges fall off it, and what stays is a heap whose
// flanks run from the platform's edges to its crest. Its free surface is the highest point
// of the grains in each column of one grain diameter; its angle is measured as the crest's
// height over the platform's half-width and as the least-squares slope of both flanks
// (away from the crest and the edges), and with the number of grains the platform holds.
#include "tridem/scene_io.hpp"
#include "tridem/snapshot.hpp"
#include "tridem/solver.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

constexpr double kD = 0.01;  ///< grain diameter (pentagon's circumscribed circle: 0.9 kD), m
constexpr double kPlatform = 16 * kD;   ///< width of the platform, m
constexpr double kColumn = 8 * kD;      ///< width of the column between the walls, m
constexpr int kRows = 17;               ///< rows of grains in the column
constexpr double kTooth = 0.3 * kD;     ///< height of the platform's teeth, m
constexpr double kDt = 3e-5;            ///< s (see below)
constexpr std::int64_t kSteps = 40000;  ///< 1.2 s: the walls clear the column at 0.7 s
constexpr double kLift = 0.3;           ///< the walls' speed, m/s

enum class Grain { Pentagon, Disc12 };

std::string vertex(double x, double y) { return fmt::format("[{:.17g}, {:.17g}]", x, y); }

std::string fixed_triangle(double ax, double ay, double bx, double by, double cx, double cy) {
  return fmt::format("[[triangle]]\nmaterial = \"grain\"\nvertices = [{}, {}, {}]\nfixed = true\n",
                     vertex(ax, ay), vertex(bx, by), vertex(cx, cy));
}

/// The scene of one heap. The time step: a member triangle of these bodies gives a
/// proven bound of about 2 µs (dt_crit is still estimated per member; issue 13), far below
/// what a body of 3 or 12 members needs; at 30 µs (forced) the heaps' energy balance
/// closes to 1.4 % of the energy dissipated, and no contact comes near the penetration limit.
Scene heap_scene(Grain grain, unsigned seed) {
  std::string s =
      fmt::format("[simulation]\nsteps = {}\ndt = {}\ngravity = [0, -9.81]\n"
                  "[[material]]\nname = \"grain\"\ndensity = 2500\npenalty = 1e6\nfriction = 0.9\n"
                  "restitution = 0.2\n",
                  kSteps, kDt);
  // A floor far below catches the grains that fall off the platform.
  s += fixed_triangle(1, -0.3, -1, -0.3, 0, -1.3);
  // The platform: a slab under a row of teeth (a rough base, the same for both heaps).
  const int teeth = static_cast<int>(std::lround(kPlatform / (0.5 * kD)));
  for (int k = 0; k < teeth; ++k) {
    const double x0 = -0.5 * kPlatform + k * 0.5 * kD;
    s += fixed_triangle(x0, 0, x0 + 0.5 * kD, 0, x0 + 0.25 * kD, kTooth);
  }
  s += fixed_triangle(0.5 * kPlatform, 0, -0.5 * kPlatform, 0, 0, -0.05);
  // The walls: two rectangles of two triangles each, rising from the teeth's tops.
  const double pitch = 0.9 * kD * 1.3225;  // a lattice loose enough for any orientation
  const double top = kTooth + (kRows + 1) * pitch + 0.1;
  for (const double side : {-1.0, 1.0}) {
    const double x = side * 0.5 * kColumn, xo = side * (0.5 * kColumn + 0.5 * kD);
    const double y = 0.32 * kD;
    for (int half = 0; half < 2; ++half) {
      std::string t =
          half == 0 ? (side < 0 ? vertex(x, y) + ", " + vertex(x, top) + ", " + vertex(xo, top)
                                : vertex(x, y) + ", " + vertex(xo, top) + ", " + vertex(x, top))
                    : (side < 0 ? vertex(x, y) + ", " + vertex(xo, top) + ", " + vertex(xo, y)
                                : vertex(x, y) + ", " + vertex(xo, y) + ", " + vertex(xo, top));
      s += fmt::format("[[triangle]]\nmaterial = \"grain\"\nvertices = [{}]\n"
                       "motion = \"prescribed\"\nvelocity = [0, {}]\n",
                       t, kLift);
    }
  }
  // The grains: sizes uniform within ±15 %, orientations at random; a disc has the area
  // of the mean pentagon (2.378 r² = 3 r'²).
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> size(0.85, 1.15), turn(0, 2 * std::numbers::pi);
  const int n = grain == Grain::Pentagon ? 5 : 12;
  const double r_mean = grain == Grain::Pentagon
                            ? 0.45 * kD
                            : 0.45 * kD * std::sqrt(2.5 * std::sin(0.4 * std::numbers::pi) / 3);
  const int columns = static_cast<int>(kColumn / pitch);
  for (int j = 0; j < kRows; ++j)
    for (int i = 0; i < columns - j % 2; ++i) {
      const double cx = -0.5 * columns * pitch + (i + 0.5 + 0.5 * (j % 2)) * pitch;
      const double cy = kTooth + 0.5 * pitch + 0.05 * kD + j * pitch;
      const double r = r_mean * size(rng), phase = turn(rng);
      std::vector<std::string> corner;
      for (int k = 0; k < n; ++k) {
        const double a = phase + 2 * std::numbers::pi * k / n;
        corner.push_back(vertex(cx + r * std::cos(a), cy + r * std::sin(a)));
      }
      s += "[[body]]\nmaterial = \"grain\"\n";
      if (grain == Grain::Pentagon) {  // triangulated by tridem (3 members)
        s += "polygon = [" + fmt::format("{}", fmt::join(corner, ", ")) + "]\n";
      } else {  // a fan of 12 triangles about the centre
        s += "triangles = [";
        for (int k = 0; k < n; ++k)
          s += fmt::format("{}[{}, {}, {}]", k ? ", " : "", vertex(cx, cy), corner[k],
                           corner[(k + 1) % n]);
        s += "]\n";
      }
    }
  Scene scene = parse_scene(s, grain == Grain::Pentagon ? "pentagon heap" : "disc heap");
  scene.simulation.backend = Backend::Cpu;
  return scene;
}

struct Heap {
  double angle_fit = 0;     ///< degrees, the flanks' least-squares slope
  double angle_height = 0;  ///< degrees, atan(crest height / half the platform)
  double fastest = 0;       ///< m/s, of a grain on the platform
  std::size_t grains = 0;   ///< bodies left on the platform
};

Heap measure(const Snapshot& s) {
  const int bins = static_cast<int>(std::lround(kPlatform / kD));
  std::vector<double> surface(static_cast<std::size_t>(bins), kTooth);
  Heap h;
  std::vector<bool> counted(s.body_count(), false);
  for (std::size_t k = 0; k < s.size(); ++k) {
    if (s.motion[k] != Motion::Free || s.y[k] < 0) continue;  // walls, and fallen grains
    h.fastest = std::max(h.fastest, std::hypot(s.vx[k], s.vy[k]));
    const auto b = static_cast<std::size_t>(s.body_of(k));
    if (!counted[b]) counted[b] = true, ++h.grains;
    const double vx[3] = {s.x1[k], s.x2[k], s.x3[k]}, vy[3] = {s.y1[k], s.y2[k], s.y3[k]};
    for (int v = 0; v < 3; ++v) {
      const int bin = static_cast<int>(std::floor((vx[v] + 0.5 * kPlatform) / kD));
      if (bin >= 0 && bin < bins)
        surface[static_cast<std::size_t>(bin)] =
            std::max(surface[static_cast<std::size_t>(bin)], vy[v]);
    }
  }
  // Both flanks as one line y = a + b |x|, from 1.5 diameters off the crest to one
  // diameter inside the edges: 12 columns.
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int bin = 0; bin < bins; ++bin) {
    const double x = std::abs(-0.5 * kPlatform + (bin + 0.5) * kD);
    if (x < 1.5 * kD || x > 0.5 * kPlatform - kD) continue;
    const double y = surface[static_cast<std::size_t>(bin)];
    n += 1, sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  h.angle_fit = -std::atan(slope) * 180 / std::numbers::pi;
  const double crest = *std::max_element(surface.begin(), surface.end()) - kTooth;
  h.angle_height = std::atan(crest / (0.5 * kPlatform)) * 180 / std::numbers::pi;
  return h;
}

Heap heap(Grain grain, unsigned seed) {
  SolverConfig config;
  config.force = true;  // kDt above the per-member bound: see heap_scene
  auto solver = make_solver(heap_scene(grain, seed), config);
  solver->advance(kSteps);
  Snapshot s;
  solver->snapshot(s, false);
  return measure(s);
}

TEST(AngleOfRepose, PentagonsStandSteeperThanDiscsOfTwelveTriangles) {
  const Heap pentagons = heap(Grain::Pentagon, 1);
  const Heap discs = heap(Grain::Disc12, 1);
  const auto report = [](const char* what, const Heap& h) {
    return fmt::format("{}: {:.1f}° (fit of the flanks), {:.1f}° (crest over half-width), {} "
                       "grains on the platform, fastest {:.2g} m/s",
                       what, h.angle_fit, h.angle_height, h.grains, h.fastest);
  };
  std::printf("%s\n%s\n", report("pentagons", pentagons).c_str(), report("discs", discs).c_str());
  RecordProperty("pentagon_angle_deg", fmt::format("{:.1f}", pentagons.angle_fit));
  RecordProperty("disc_angle_deg", fmt::format("{:.1f}", discs.angle_fit));
  // Both heaps came to rest (a grain of 1 cm moving at 1 cm/s would still be flowing).
  EXPECT_LT(pentagons.fastest, 0.01);
  EXPECT_LT(discs.fastest, 0.01);
  // Both are heaps, not a spread layer: some dozens of grains stayed on the platform.
  EXPECT_GT(pentagons.grains, 30u);
  EXPECT_GT(discs.grains, 30u);
  // The trend. One heap's surface is noisy: the flanks' fit moved by up to 10° between two
  // arrangements of the same grains (docs/validation-bodies.md) and does not separate the
  // shapes in a single heap, so it is reported, not asserted. What separated them in every
  // heap measured (3 pairs, friction 0.5 and 0.9) is the heap's height and what the
  // platform holds: the crest over the half-width 2.7 to 8.1° steeper for pentagons
  // (here 32.2° against 29.5°), and 11 to 12 more pentagons than discs kept on the
  // platform (73 against 61). A fixed base holds a heap of area (W/2)² tan θ, and angular
  // grains pack no denser than round ones, so more grains held is a steeper heap. The
  // margins are about half of the smallest differences measured.
  EXPECT_GT(pentagons.angle_height, discs.angle_height + 1.5)
      << report("pentagons", pentagons) << "\n"
      << report("discs", discs);
  EXPECT_GE(pentagons.grains, discs.grains + 6) << report("pentagons", pentagons) << "\n"
                                                << report("discs", discs);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
