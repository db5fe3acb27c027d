// Lattice generator. Geometry: a triangular tiling of edge a = size·(1 + gap·√3); each tile
// is shrunk about its centroid to edge `size`. Facing edges of neighbouring tiles coincide,
// and each shrinks towards its own centroid by the inradius difference (a − size)/(2√3), so
// the particles end up gap·size apart. Rows are offset by a/2 as in a true triangular
// lattice; in every row the particles' left corners sit at xmin + k·a/2 with up and down
// triangles alternating, which is what makes counting them in closed form easy.
#include "tridem/generate.hpp"

#include "io/scene/generator_checks.hpp"

#include <algorithm>
#include <cmath>

namespace tridem {
namespace {

struct LatticeGeometry {
  double s;           // particle edge
  double half_pitch;  // a/2: horizontal step between successive particles in a row
  double row_pitch;   // a·√3/2: vertical step between rows
  double h;           // particle height s·√3/2
  double down_top;    // top edge of row 0's down triangles, above ymin
  double k_max;       // last horizontal slot index that fits (may be < 0: none)
  double rows_up;     // rows whose up triangles fit
  double rows_down;   // rows whose down triangles fit
};

LatticeGeometry geometry_of(const LatticeSpec& spec) {
  const double sqrt3 = std::sqrt(3.0);
  LatticeGeometry g{};
  g.s = spec.size;
  const double a = spec.size * (1 + spec.gap * sqrt3);
  g.half_pitch = 0.5 * a;
  g.row_pitch = 0.5 * sqrt3 * a;
  g.h = 0.5 * sqrt3 * spec.size;
  // Up bases sit on ymin; a down triangle's top is its tile's top, lowered by gap·size/2.
  // Relative to the up apex of the same row that is gap·size/2 higher (see the header).
  g.down_top = g.row_pitch - spec.gap * spec.size;
  const double width = spec.region_max.x - spec.region_min.x;
  const double height = spec.region_max.y - spec.region_min.y;
  g.k_max = width >= g.s ? scene_detail::tolerant_floor((width - g.s) / g.half_pitch) : -1;
  g.rows_up = height >= g.h ? scene_detail::tolerant_floor((height - g.h) / g.row_pitch) + 1 : 0;
  g.rows_down = height >= g.down_top
                    ? scene_detail::tolerant_floor((height - g.down_top) / g.row_pitch) + 1
                    : 0;
  return g;
}

// Up triangles take the even slots of even rows and the odd slots of odd rows; down
// triangles the rest. Counts of rows and slots stay in double until the end because a
// units mistake can make them overflow any integer.
double count_of(const LatticeGeometry& g) {
  if (g.k_max < 0) return 0;
  const double slots = g.k_max + 1;
  const double even_slots = std::ceil(slots / 2), odd_slots = std::floor(slots / 2);
  auto even_rows = [](double rows) { return std::ceil(rows / 2); };
  auto odd_rows = [](double rows) { return std::floor(rows / 2); };
  const double ups = even_rows(g.rows_up) * even_slots + odd_rows(g.rows_up) * odd_slots;
  const double downs = even_rows(g.rows_down) * odd_slots + odd_rows(g.rows_down) * even_slots;
  return ups + downs;
}

}  // namespace

std::size_t count_lattice(const LatticeSpec& spec) {
  scene_detail::check_generator_common("lattice", spec.material, spec.region_min,
                                       spec.region_max, spec.size, spec.gap, spec.velocity);
  return scene_detail::saturating_count(count_of(geometry_of(spec)));
}

std::vector<TriangleSpec> generate_lattice(const LatticeSpec& spec) {
  const std::size_t n = count_lattice(spec);
  scene_detail::check_generated_count("lattice", n);
  const LatticeGeometry g = geometry_of(spec);
  const auto slots = static_cast<long long>(g.k_max) + 1;
  const auto rows = static_cast<long long>(g.rows_up);  // rows_down <= rows_up

  // Each row's first id, so that the rows are filled on the threads in the order one
  // thread would fill them (a 10^7 lattice, issue 12): a row holds its up triangles, and
  // its down ones where they fit.
  std::vector<std::size_t> row_first(static_cast<std::size_t>(std::max(rows, 0LL)) + 1, 0);
  for (long long j = 0; j < rows; ++j) {
    const long long ups = j % 2 == 0 ? (slots + 1) / 2 : slots / 2;
    const bool downs_fit = static_cast<double>(j) < g.rows_down;
    const auto row = static_cast<std::size_t>(j);
    row_first[row + 1] = row_first[row] + static_cast<std::size_t>(downs_fit ? slots : ups);
  }
  std::vector<TriangleSpec> out(n);
  const Vec2d o = spec.region_min;
#pragma omp parallel for schedule(static) if (n > 65536)
  for (long long j = 0; j < rows; ++j) {
    const double row_base = o.y + static_cast<double>(j) * g.row_pitch;
    const bool downs_fit = static_cast<double>(j) < g.rows_down;
    std::size_t id = row_first[static_cast<std::size_t>(j)];
    for (long long k = 0; k < slots; ++k) {
      const double left = o.x + static_cast<double>(k) * g.half_pitch;
      const bool up = (j + k) % 2 == 0;
      if (!up && !downs_fit) continue;
      TriangleSpec& t = out[id++];
      if (up) {
        t.vertices = {Vec2d{left, row_base}, Vec2d{left + g.s, row_base},
                      Vec2d{left + 0.5 * g.s, row_base + g.h}};
      } else {
        const double top = row_base + g.down_top;
        t.vertices = {Vec2d{left + 0.5 * g.s, top - g.h}, Vec2d{left + g.s, top},
                      Vec2d{left, top}};
      }
      t.material = spec.material;
      t.velocity = spec.velocity;
    }
  }
  return out;
}

}  // namespace tridem
