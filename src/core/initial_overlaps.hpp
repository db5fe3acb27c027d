#pragma once
// Triangles that overlap before the first step. The contact force of an overlap is
// elastic energy the scene did not mean to hold: a grain placed 4 mm into a floor is shot
// off with it. The reader refuses such scenes (validate_scene); `[simulation]
// relax_overlaps = true` asks run_scene to push them apart first, moving positions only.
//
// Overlap is the separating-axis test (physics::overlap_depth) on the pairs the cell grid
// of the solvers (CandidatePairs) lists, so the check is O(n). Pairs of two walls are
// skipped, as the solvers skip them; touching (a depth within rounding of zero) is allowed.
// In a periodic cell a triangle is tested against its partners' nearest images, as the
// solvers' pairs see them at t = 0, so an overlap through the boundary is one too.
#include "tridem/scene.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace tridem {

/// Depths up to this fraction of the pair's longest edge count as touching: rounding of
/// vertices placed edge to edge (a lattice with gap = 0) is far below it.
inline constexpr double kTouchingTolerance = 1e-9;

struct InitialOverlap {
  std::size_t a = 0, b = 0;  ///< particle ids, a < b
  double depth = 0;          ///< shortest push along an edge normal that separates them, m
  Vec2d push{};              ///< unit direction b must move in (a the opposite way)
};

/// Every overlapping pair, ordered by (a, b). With a periodic `cell`, a pair overlaps when
/// one overlaps the other's nearest image (the rule of the solvers' pairs at t = 0).
std::vector<InitialOverlap> find_initial_overlaps(const std::vector<TriangleSpec>& triangles,
                                                  const PeriodicCell& cell = {});

/// The first overlapping pair (lowest a, then b), or none.
std::optional<InitialOverlap> first_initial_overlap(const std::vector<TriangleSpec>& triangles,
                                                    const PeriodicCell& cell = {});

/// The first overlapping pair (lowest a, then b) among those `counts(a, b)` accepts (a < b),
/// or none. A pair it refuses is not tested at all: a scene that keeps the overlaps of its
/// imported grains (some 6x10^6 pairs at 10^6 triangles) tests only the others.
std::optional<InitialOverlap> first_initial_overlap_where(
    const std::vector<TriangleSpec>& triangles, const PeriodicCell& cell,
    const std::function<bool(std::size_t a, std::size_t b)>& counts);

/// What relax_initial_overlaps did, for the run's log.
struct RelaxReport {
  int iterations = 0;
  std::size_t pairs = 0;          ///< overlapping pairs at the start
  std::size_t moved = 0;          ///< particles moved
  double deepest = 0;             ///< deepest overlap at the start, m
  double largest_move = 0;        ///< longest total displacement of one particle, m
  std::int64_t first_moved = -1;  ///< lowest id moved (-1: none)
};

/// Pushes overlapping triangles apart by translating them, velocities untouched, so that
/// the run starts with no contact energy: each iteration moves both triangles of every
/// overlapping pair apart along its separating direction by the depth (shared in inverse
/// proportion to mass; a wall does not move), until no overlap is left. A body of several
/// triangles moves as one (its members by the same translation; two bodies push once,
/// along their deepest pair of members). Throws SceneError
/// naming the deepest remaining pair when `max_iterations` do not separate them.
RelaxReport relax_initial_overlaps(Scene& scene, int max_iterations = 1000);

}  // namespace tridem
