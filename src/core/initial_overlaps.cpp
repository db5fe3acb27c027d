#include "core/initial_overlaps.hpp"

#include "broadphase/candidate_pairs.hpp"
#include "broadphase/default_init_allocator.hpp"
#include "physics/geometry.hpp"
#include "tridem/error.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <omp.h>

namespace tridem {

namespace {

physics::Triangle<double> counter_clockwise(const TriangleSpec& t) {
  physics::Triangle<double> tri{{t.vertices[0], t.vertices[1], t.vertices[2]}};
  if (physics::signed_area(tri) < 0) std::swap(tri.v[1], tri.v[2]);
  return tri;
}

/// The triangles as the grid sees them: boxes, longest edges, motions.
/// Built on the threads, and its boxes and centroids left unfilled until then (a 10^7
/// scene's check, issue 12); the grid takes the longest edges and motions as vectors.
struct Layout {
  std::vector<physics::Triangle<double>> tri;
  UnfilledVector<double> lo_x, lo_y, hi_x, hi_y;
  std::vector<double> longest;
  UnfilledVector<double> cx, cy;  ///< centroids, from which a pair takes its periodic image
  std::vector<Motion> motion;
  std::optional<physics::PeriodicFrame> frame;  ///< the periodic cell at t = 0, if any

  Layout(const std::vector<TriangleSpec>& triangles, const PeriodicCell& cell) {
    const std::size_t n = triangles.size();
    tri.resize(n);
    for (auto* v : {&lo_x, &lo_y, &hi_x, &hi_y, &cx, &cy}) v->resize(n);
    longest.resize(n);
    // validate_scene refuses other cells before it looks for overlaps.
    const auto usable = [](const std::optional<PeriodicRange>& r) {
      return !r || (std::isfinite(r->length()) && r->length() > 0);
    };
    if (cell.any() && usable(cell.x) && usable(cell.y)) frame = periodic_frame_of(cell, 0);
    motion.resize(n);
    const auto count = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel for schedule(static) if (count > 65536)
    for (std::ptrdiff_t signed_i = 0; signed_i < count; ++signed_i) {
      const auto i = static_cast<std::size_t>(signed_i);
      tri[i] = counter_clockwise(triangles[i]);
      longest[i] = physics::longest_edge(tri[i]);
      motion[i] = triangles[i].motion;
    }
    update_boxes();
  }
  void update_boxes() {
    const auto count = static_cast<std::ptrdiff_t>(tri.size());
#pragma omp parallel for schedule(static) if (count > 65536)
    for (std::ptrdiff_t signed_i = 0; signed_i < count; ++signed_i) {
      const auto i = static_cast<std::size_t>(signed_i);
      const physics::Aabb<double> box = physics::bounding_box(tri[i]);
      lo_x[i] = box.lo.x;
      lo_y[i] = box.lo.y;
      hi_x[i] = box.hi.x;
      hi_y[i] = box.hi.y;
      const Vec2d c = physics::centroid(tri[i]);
      cx[i] = c.x;
      cy[i] = c.y;
    }
  }
  BoxArrays<double> boxes() const { return {lo_x.data(), lo_y.data(), hi_x.data(), hi_y.data()}; }
  void find(CandidatePairs<double>& grid, PairList& pairs) const {
    if (!frame) return grid.find(boxes(), Method::Grid, true, pairs);
    const PeriodicView view{*frame, cx.data(), cy.data()};
    grid.find(boxes(), Method::Grid, true, pairs, &view);
  }
  /// j as e meets it: j itself, or its nearest periodic image.
  physics::Triangle<double> partner(std::int64_t e, std::int64_t j) const {
    physics::Triangle<double> t = tri[j];
    if (!frame) return t;
    const physics::PeriodicImage im =
        physics::nearest_image(*frame, Vec2d{cx[e], cy[e]}, Vec2d{cx[j], cy[j]});
    for (Vec2d& v : t.v) v += im.shift;
    return t;
  }
};

/// A depth that is more than rounding: a fraction of the pair's size, and a few ulps of
/// its coordinates (a small grain far from the origin).
double touching_tolerance(const physics::Triangle<double>& a, const physics::Triangle<double>& b,
                          double longest) {
  double coordinate = 0;
  for (const auto* t : {&a, &b})
    for (const Vec2d& v : t->v) coordinate = std::max({coordinate, std::abs(v.x), std::abs(v.y)});
  return kTouchingTolerance * longest + 64 * 2.220446049250313e-16 * coordinate;
}

/// How deep e and j (its image) overlap, and whether that is more than touching.
bool overlapping(const Layout& layout, std::int64_t e, std::int32_t j, double& depth, Vec2d& push) {
  const physics::Triangle<double> other = layout.partner(e, j);
  depth = physics::overlap_depth(layout.tri[e], other, push);
  const double l = std::max(layout.longest[e], layout.longest[j]);
  return depth > touching_tolerance(layout.tri[e], other, l);
}

/// The overlapping pairs among the grid's candidates, by emitter then partner.
std::vector<InitialOverlap> overlaps(const Layout& layout, CandidatePairs<double>& grid,
                                     PairList& pairs, bool first_only) {
  layout.find(grid, pairs);
  const auto n = static_cast<std::int64_t>(layout.tri.size());
  // Each emitter keeps its first overlap only for the refusal; the lowest is reported.
  std::int64_t first = n;
  std::vector<InitialOverlap> found;
  if (first_only) {
#pragma omp parallel for schedule(dynamic, 1024) reduction(min : first)
    for (std::int64_t e = 0; e < n; ++e)
      for (std::int64_t s = pairs.offset[e]; s < pairs.offset[e + 1]; ++s) {
        Vec2d push;
        double depth = 0;
        if (overlapping(layout, e, pairs.partner[s], depth, push)) {
          first = std::min(first, e);
          break;
        }
      }
    if (first == n) return found;
  }
  // The overlaps of emitter e, each once, ids in ascending order (the emitter of a small
  // particle and a wall is the small one); only the first when `first_only`.
  auto emitter_overlaps = [&](std::int64_t e, std::vector<InitialOverlap>& out) {
    for (std::int64_t s = pairs.offset[e]; s < pairs.offset[e + 1]; ++s) {
      const std::int32_t j = pairs.partner[s];
      InitialOverlap o{static_cast<std::size_t>(e), static_cast<std::size_t>(j), 0, {}};
      if (!overlapping(layout, e, j, o.depth, o.push)) continue;
      if (o.a > o.b) {
        std::swap(o.a, o.b);
        o.push = -o.push;
      }
      out.push_back(o);
      if (first_only) return;
    }
  };
  if (first_only) {
    emitter_overlaps(first, found);
    return found;
  }
  // Every pair on the threads (a scene imported with keep_overlaps walks all of them: at
  // 10^6 triangles some 6x10^6 pairs), each thread's finds gathered, then sorted: the same
  // list whatever the threads.
  std::vector<std::vector<InitialOverlap>> per_thread(
      static_cast<std::size_t>(omp_get_max_threads()));
#pragma omp parallel
  {
    std::vector<InitialOverlap>& mine = per_thread[static_cast<std::size_t>(omp_get_thread_num())];
#pragma omp for schedule(dynamic, 1024)
    for (std::int64_t e = 0; e < n; ++e) emitter_overlaps(e, mine);
  }
  for (const std::vector<InitialOverlap>& part : per_thread)
    found.insert(found.end(), part.begin(), part.end());
  std::sort(found.begin(), found.end(), [](const InitialOverlap& x, const InitialOverlap& y) {
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  });
  return found;
}

}  // namespace

std::vector<InitialOverlap> find_initial_overlaps(const std::vector<TriangleSpec>& triangles,
                                                  const PeriodicCell& cell) {
  if (triangles.empty()) return {};
  const Layout layout(triangles, cell);
  CandidatePairs<double> grid(layout.longest, layout.motion);
  PairList pairs;
  return overlaps(layout, grid, pairs, false);
}

std::optional<InitialOverlap> first_initial_overlap(const std::vector<TriangleSpec>& triangles,
                                                    const PeriodicCell& cell) {
  if (triangles.empty()) return std::nullopt;
  const Layout layout(triangles, cell);
  CandidatePairs<double> grid(layout.longest, layout.motion);
  PairList pairs;
  const std::vector<InitialOverlap> found = overlaps(layout, grid, pairs, true);
  if (found.empty()) return std::nullopt;
  return found.front();
}

std::optional<InitialOverlap> first_initial_overlap_where(
    const std::vector<TriangleSpec>& triangles, const PeriodicCell& cell,
    const std::function<bool(std::size_t a, std::size_t b)>& counts) {
  if (triangles.empty()) return std::nullopt;
  const Layout layout(triangles, cell);
  CandidatePairs<double> grid(layout.longest, layout.motion);
  PairList pairs;
  layout.find(grid, pairs);
  const auto n = static_cast<std::int64_t>(layout.tri.size());
  auto before = [](const InitialOverlap& x, const std::optional<InitialOverlap>& y) {
    return !y || (x.a != y->a ? x.a < y->a : x.b < y->b);
  };
  // Each thread's first, then the first of those: the same pair on any number of threads.
  std::vector<std::optional<InitialOverlap>> first(static_cast<std::size_t>(omp_get_max_threads()));
#pragma omp parallel
  {
    std::optional<InitialOverlap>& mine = first[static_cast<std::size_t>(omp_get_thread_num())];
#pragma omp for schedule(dynamic, 1024)
    for (std::int64_t e = 0; e < n; ++e)
      for (std::int64_t s = pairs.offset[e]; s < pairs.offset[e + 1]; ++s) {
        const std::int32_t j = pairs.partner[s];
        const auto ue = static_cast<std::size_t>(e), uj = static_cast<std::size_t>(j);
        if (!counts(std::min(ue, uj), std::max(ue, uj))) continue;
        InitialOverlap o{ue, uj, 0, {}};
        if (!overlapping(layout, e, j, o.depth, o.push)) continue;
        if (o.a > o.b) {
          std::swap(o.a, o.b);
          o.push = -o.push;
        }
        if (before(o, mine)) mine = o;
      }
  }
  std::optional<InitialOverlap> out;
  for (const std::optional<InitialOverlap>& o : first)
    if (o && before(*o, out)) out = o;
  return out;
}

namespace {

/// The rigid units relax_initial_overlaps moves: a body of several triangles, or a lone
/// triangle. Members move together, by one translation, so a body keeps its shape.
struct Units {
  std::vector<std::size_t> of;     ///< per triangle: its unit
  std::vector<std::size_t> first;  ///< members of unit u: triangles [first[u], first[u+1])
  std::vector<double> inv_mass;    ///< 0 for a wall

  Units(const Scene& scene, const Layout& layout) {
    const std::size_t n = layout.tri.size();
    of.resize(n);
    if (scene.bodies.empty()) {
      first.resize(n + 1);
      for (std::size_t i = 0; i <= n; ++i) first[i] = i;
    } else {
      for (const BodySpec& b : scene.bodies) first.push_back(b.first);
      first.push_back(n);
    }
    inv_mass.assign(first.size() - 1, 0.0);
    for (std::size_t u = 0; u + 1 < first.size(); ++u) {
      double mass = 0;
      for (std::size_t i = first[u]; i < first[u + 1]; ++i) {
        of[i] = u;
        mass += scene.materials[scene.triangles[i].material].density *
                physics::signed_area(layout.tri[i]);
      }
      if (layout.motion[first[u]] == Motion::Free) inv_mass[u] = 1.0 / mass;
    }
  }
  std::size_t size() const { return inv_mass.size(); }
};

/// A body's motion is its members' (a member's own is ignored, docs/scene-format.md).
void take_body_motions(const Scene& scene, Layout& layout) {
  for (const BodySpec& b : scene.bodies)
    for (std::size_t i = b.first; i < b.first + b.count; ++i) layout.motion[i] = b.motion;
}

}  // namespace

RelaxReport relax_initial_overlaps(Scene& scene, int max_iterations) {
  RelaxReport report;
  if (scene.triangles.empty()) return report;
  Layout layout(scene.triangles, scene.simulation.periodic);
  take_body_motions(scene, layout);
  const std::size_t n = layout.tri.size();
  // A wall does not move; grains share a push in inverse proportion to their masses.
  const Units units(scene, layout);
  CandidatePairs<double> grid(layout.longest, layout.motion);
  PairList pairs;
  std::vector<Vec2d> total(units.size()), step(units.size());
  struct UnitPush {
    std::size_t a, b;
    double depth;
    Vec2d push;
  };
  std::vector<UnitPush> pushes;
  for (;;) {
    std::vector<InitialOverlap> found = overlaps(layout, grid, pairs, false);
    // Members of one body never interact: their shared edges are not overlaps.
    std::erase_if(found,
                  [&units](const InitialOverlap& o) { return units.of[o.a] == units.of[o.b]; });
    if (report.iterations == 0) {
      report.pairs = found.size();
      for (const InitialOverlap& o : found) report.deepest = std::max(report.deepest, o.depth);
    }
    if (found.empty()) break;
    if (report.iterations == max_iterations) {
      const auto deepest = std::max_element(
          found.begin(), found.end(),
          [](const InitialOverlap& x, const InitialOverlap& y) { return x.depth < y.depth; });
      const std::string source = scene.source.empty() ? "scene built in code" : scene.source;
      throw SceneError(fmt::format(
          "{}: relax_overlaps could not separate the initial overlaps in {} iterations: "
          "particles {} and {} still overlap by {:.6g} m ({} pairs left); move them apart in "
          "the scene",
          source, max_iterations, deepest->a, deepest->b, deepest->depth, found.size()));
    }
    // Two bodies push once, along their deepest members' pair: several member pairs of
    // the same two bodies would add up to more than the overlap.
    pushes.clear();
    for (const InitialOverlap& o : found)
      pushes.push_back({units.of[o.a], units.of[o.b], o.depth, o.push});
    std::stable_sort(pushes.begin(), pushes.end(), [](const UnitPush& x, const UnitPush& y) {
      return x.a != y.a ? x.a < y.a : (x.b != y.b ? x.b < y.b : x.depth > y.depth);
    });
    pushes.erase(
        std::unique(pushes.begin(), pushes.end(),
                    [](const UnitPush& x, const UnitPush& y) { return x.a == y.a && x.b == y.b; }),
        pushes.end());
    // Jacobi: every pair pushes from the same positions, the pushes add up.
    std::fill(step.begin(), step.end(), Vec2d{});
    for (const UnitPush& o : pushes) {
      const double wa = units.inv_mass[o.a], wb = units.inv_mass[o.b];
      // A hair beyond the depth, so that rounding does not leave the pair just overlapping.
      const double d = o.depth * (1 + 1e-6);
      step[o.a] -= o.push * (d * wa / (wa + wb));
      step[o.b] += o.push * (d * wb / (wa + wb));
    }
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2d move = step[units.of[i]];
      if (move.x == 0 && move.y == 0) continue;
      for (Vec2d& v : layout.tri[i].v) v += move;
      for (Vec2d& v : scene.triangles[i].vertices) v += move;
    }
    for (std::size_t u = 0; u < units.size(); ++u) total[u] += step[u];
    layout.update_boxes();
    ++report.iterations;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double moved = norm(total[units.of[i]]);
    if (moved == 0) continue;
    if (report.first_moved < 0) report.first_moved = static_cast<std::int64_t>(i);
    ++report.moved;
    report.largest_move = std::max(report.largest_move, moved);
  }
  return report;
}

}  // namespace tridem
