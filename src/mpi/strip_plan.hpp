#pragma once
// Where each particle lives on N ranks (pure host code, no MPI: tested on its own).
//
// The free particles are cut into N domains, each holding about the same work: a particle
// weighs 1 + its contacts (the pairs with contact history), so the borders move to balance
// contacts, not particles. The domains are strips, or a grid of nx × ny = N (columns cut
// along x, each column's rows along y) where its borders are shorter: of the factorings of
// N, the one whose inner borders across the grains' extent are the shortest (strips across
// the longer side on a tie, and for a prime N). Each rank owns (steps and reports) the
// particles of its domain and holds besides them, as ghosts whose state its owner sends
// every step:
//  - every free particle whose centroid is within `margin` = 2 R + skin of its own
//    particles' extent along each cut axis (R: the largest distance of a vertex from its
//    centroid), so that every particle that can touch one of its own is there until some
//    particle has moved half the skin from where the plan saw it;
//  - the free particle with the longest edge: it sets the cell grid's size, so that every
//    rank bins, and picks emitters, as one rank does;
//  - in a periodic cell, distances along a periodic axis are taken through the boundary
//    (the nearest image's): the strips form a ring along it. With Lees-Edwards shear the
//    strips are cut along y, so that each runs the whole period in x, where the images
//    across the y boundary slide;
//  - every wall (fixed or prescribed particle): each rank steps them itself, identically.
//    A wall no longer than the cell size emits its pairs with higher ids (emitter_rule.hpp):
//    it is owned like a grain (its row, and the energy the row adds to it, then live on one
//    rank); rank 0 reports the other walls.
#include "tridem/scene.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace tridem::mpi {

struct StripInput {
  std::vector<double> x, y;  ///< centroids
  std::vector<Motion> motion;
  std::vector<double> radius;  ///< farthest vertex from the centroid
  std::vector<double> longest_edge;
  std::vector<std::int32_t> contacts;  ///< pairs with history, per particle
  /// Bodies of several triangles: per particle, the first member of its body (itself for
  /// a lone triangle); empty when there are none. A body's members are consecutive ids;
  /// they are owned together (by the rank of the first member's centroid) and held
  /// together (all of them where any of them is).
  std::vector<std::int32_t> unit;
  /// Cohesive bonds (a, b): a rank holds the bond partners of every particle it owns, so
  /// that each of its particles has all its bonds.
  std::vector<std::array<std::int32_t, 2>> bonds;
  int ranks = 1;
  double skin = 0;
  /// Periodic axes (x, y) and their periods; `sheared`: Lees-Edwards (both periodic).
  bool periodic[2] = {false, false};
  double period[2] = {0, 0};
  bool sheared = false;
};

struct StripPlan {
  int axis = 0;          ///< strips: 0 across x (cut at x = const), 1 across y; a grid: 0
  int cuts[2] = {1, 1};  ///< domains along x and along y (their product is N)
  double margin = 0;  ///< 2 R + skin
  /// Per particle: its rank; -1 for a wall that emits nothing (rank 0 reports it).
  std::vector<int> owner;
  /// Per rank: every particle it holds (own, ghosts, walls), ascending.
  std::vector<std::vector<std::int32_t>> held;
  /// Per rank and axis: the lowest and highest centroid coordinate of its own particles
  /// (lo > hi for a rank that owns none).
  std::vector<std::array<double, 2>> lo, hi;

  bool grid() const { return cuts[0] > 1 && cuts[1] > 1; }
  std::int32_t cell_setter = -1;  ///< the free particle of the longest edge (-1: none free)

  bool owns(int rank, std::int32_t i) const { return owner[static_cast<std::size_t>(i)] == rank; }
};

/// The plan for `in` (deterministic: every rank computes the same one from the same input).
StripPlan plan_strips(const StripInput& in);

}  // namespace tridem::mpi
