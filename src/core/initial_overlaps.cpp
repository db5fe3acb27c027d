#include "core/initial_overlaps.hpp"

#include "broadphase/candidate_pairs.hpp"
#include "physics/geometry.hpp"
#include "tridem/error.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace tridem {

namespace {

physics::Triangle<double> counter_clockwise(const TriangleSpec& t) {
  physics::Triangle<double> tri{{t.vertices[0], t.vertices[1], t.vertices[2]}};
  if (physics::signed_area(tri) < 0) std::swap(tri.v[1], tri.v[2]);
  return tri;
}

/// The triangles as the grid sees them: boxes, longest edges, motions.
struct Layout {
  std::vector<physics::Triangle<double>> tri;
  std::vector<double> lo_x, lo_y, hi_x, hi_y, longest;
  std::vector<Motion> motion;

  explicit Layout(const std::vector<TriangleSpec>& triangles) {
    const std::size_t n = triangles.size();
    tri.resize(n);
    for (auto* v : {&lo_x, &lo_y, &hi_x, &hi_y, &longest}) v->resize(n);
    motion.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      tri[i] = counter_clockwise(triangles[i]);
      longest[i] = physics::longest_edge(tri[i]);
      motion[i] = triangles[i].motion;
    }
    update_boxes();
  }
  void update_boxes() {
    for (std::size_t i = 0; i < tri.size(); ++i) {
      const physics::Aabb<double> box = physics::bounding_box(tri[i]);
      lo_x[i] = box.lo.x;
      lo_y[i] = box.lo.y;
      hi_x[i] = box.hi.x;
      hi_y[i] = box.hi.y;
    }
  }
  BoxArrays<double> boxes() const { return {lo_x.data(), lo_y.data(), hi_x.data(), hi_y.data()}; }
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

/// The overlapping pairs among the grid's candidates, by emitter then partner.
std::vector<InitialOverlap> overlaps(const Layout& layout, CandidatePairs<double>& grid,
                                     PairList& pairs, bool first_only) {
  grid.find(layout.boxes(), Method::Grid, true, pairs);
  const auto n = static_cast<std::int64_t>(layout.tri.size());
  // Each emitter keeps its first overlap only for the refusal; the lowest is reported.
  std::int64_t first = n;
  std::vector<InitialOverlap> found;
  if (first_only) {
#pragma omp parallel for schedule(dynamic, 1024) reduction(min : first)
    for (std::int64_t e = 0; e < n; ++e)
      for (std::int64_t s = pairs.offset[e]; s < pairs.offset[e + 1]; ++s) {
        const std::int32_t j = pairs.partner[s];
        Vec2d push;
        const double depth = physics::overlap_depth(layout.tri[e], layout.tri[j], push);
        const double l = std::max(layout.longest[e], layout.longest[j]);
        if (depth > touching_tolerance(layout.tri[e], layout.tri[j], l)) {
          first = std::min(first, e);
          break;
        }
      }
    if (first == n) return found;
  }
  const std::int64_t begin = first_only ? first : 0, end = first_only ? first + 1 : n;
  for (std::int64_t e = begin; e < end; ++e)
    for (std::int64_t s = pairs.offset[e]; s < pairs.offset[e + 1]; ++s) {
      const std::int32_t j = pairs.partner[s];
      InitialOverlap o{static_cast<std::size_t>(e), static_cast<std::size_t>(j), 0, {}};
      o.depth = physics::overlap_depth(layout.tri[e], layout.tri[j], o.push);
      const double l = std::max(layout.longest[e], layout.longest[j]);
      if (!(o.depth > touching_tolerance(layout.tri[e], layout.tri[j], l))) continue;
      // Ids in ascending order (the emitter of a small particle and a wall is the small one).
      if (o.a > o.b) {
        std::swap(o.a, o.b);
        o.push = -o.push;
      }
      found.push_back(o);
      if (first_only) return found;
    }
  std::sort(found.begin(), found.end(), [](const InitialOverlap& x, const InitialOverlap& y) {
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  });
  return found;
}

}  // namespace

std::vector<InitialOverlap> find_initial_overlaps(const std::vector<TriangleSpec>& triangles) {
  if (triangles.empty()) return {};
  const Layout layout(triangles);
  CandidatePairs<double> grid(layout.longest, layout.motion);
  PairList pairs;
  return overlaps(layout, grid, pairs, false);
}

std::optional<InitialOverlap> first_initial_overlap(const std::vector<TriangleSpec>& triangles) {
  if (triangles.empty()) return std::nullopt;
  const Layout layout(triangles);
  CandidatePairs<double> grid(layout.longest, layout.motion);
  PairList pairs;
  const std::vector<InitialOverlap> found = overlaps(layout, grid, pairs, true);
  if (found.empty()) return std::nullopt;
  return found.front();
}

RelaxReport relax_initial_overlaps(Scene& scene, int max_iterations) {
  RelaxReport report;
  if (scene.triangles.empty()) return report;
  // It moves triangles one by one, which would tear a body's members apart (issue 13).
  if (scene.has_bodies())
    throw SceneError(scene.source + ": [simulation] relax_overlaps = true does not work with "
                                    "[[body]] blocks of several triangles yet; move the "
                                    "overlapping particles apart in the file instead");
  Layout layout(scene.triangles);
  const std::size_t n = layout.tri.size();
  // A wall does not move; grains share a push in inverse proportion to their masses.
  std::vector<double> inv_mass(n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    if (layout.motion[i] == Motion::Free)
      inv_mass[i] = 1.0 / (scene.materials[scene.triangles[i].material].density *
                           physics::signed_area(layout.tri[i]));
  CandidatePairs<double> grid(layout.longest, layout.motion);
  PairList pairs;
  std::vector<Vec2d> total(n), step(n);
  for (;;) {
    const std::vector<InitialOverlap> found = overlaps(layout, grid, pairs, false);
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
    // Jacobi: every pair pushes from the same positions, the pushes add up.
    std::fill(step.begin(), step.end(), Vec2d{});
    for (const InitialOverlap& o : found) {
      const double wa = inv_mass[o.a], wb = inv_mass[o.b];
      // A hair beyond the depth, so that rounding does not leave the pair just overlapping.
      const double d = o.depth * (1 + 1e-6);
      step[o.a] -= o.push * (d * wa / (wa + wb));
      step[o.b] += o.push * (d * wb / (wa + wb));
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (step[i].x == 0 && step[i].y == 0) continue;
      for (Vec2d& v : layout.tri[i].v) v += step[i];
      for (Vec2d& v : scene.triangles[i].vertices) v += step[i];
      total[i] += step[i];
    }
    layout.update_boxes();
    ++report.iterations;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double moved = norm(total[i]);
    if (moved == 0) continue;
    if (report.first_moved < 0) report.first_moved = static_cast<std::int64_t>(i);
    ++report.moved;
    report.largest_move = std::max(report.largest_move, moved);
  }
  return report;
}

}  // namespace tridem
