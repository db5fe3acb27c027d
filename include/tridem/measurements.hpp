#pragma once
// The measurements researchers report of a granular packing (docs/experiments.md,
// "Measurements"), computed on the host from a Snapshot that holds its contacts
// (Solver::snapshot(out, true)): the same for every backend, and a pure function of the
// snapshot, so that any front end (the [[measure]] logs, the frames, a script) can call them.
//
// A grain is a body: a body of several triangles is one grain, a lone triangle another.
// Free grains are measured; fixed and prescribed ones are walls, whose contacts count for
// the free grains that touch them.
#include "tridem/scene.hpp"
#include "tridem/snapshot.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace tridem {

/// The averages over one region at one step. Stresses in Pa·m/m = N/m per unit thickness
/// (2D: force per length), compression positive. Ratios with nothing to average (no grain,
/// no contact) are NaN.
struct Measurement {
  std::int64_t step = 0;
  double time = 0;
  double area = 0;             ///< of the region (the free grains' bounding box without one)
  std::int64_t particles = 0;  ///< free grains whose centroid is inside
  std::int64_t contacts = 0;   ///< grain contacts with at least one of those grains
  std::int64_t rattlers = 0;   ///< of those grains, the rattlers
  /// Love-Weber: −(1/A) Σ_p Σ_c f_i (x_c − x_p)_j over the grains p inside and their
  /// contacts c (force f on p, applied at x_c; x_p the grain's centroid).
  double sxx = 0, sxy = 0, syx = 0, syy = 0;
  double pressure = 0;          ///< (sxx + syy) / 2
  double deviatoric = 0;        ///< √(((sxx − syy)/2)² + ((sxy + syx)/2)²), the Mohr radius
  double packing_fraction = 0;  ///< free triangles' area inside the region, over its area
  double coordination = 0;      ///< contacts per grain inside (walls' contacts included)
  double mechanical_coordination = 0;  ///< the same without rattlers and their contacts
  double fabric_xx = 0, fabric_xy = 0, fabric_yy = 0;  ///< <n_i n_j> over the grains' contacts
  double mean_overlap = 0, max_overlap = 0;            ///< penetration depth φ of the contacts
};

/// The measurements over `region` (nullopt: every free grain, over their bounding box).
Measurement measure_region(const Snapshot& s, const std::optional<MeasureRegion>& region);

/// Per grain (body id order, Snapshot::body_count()): its own Love-Weber sum over its
/// contacts divided by its area, −(1/A_p) Σ_c f_i (x_c − x_p)_j (compression positive),
/// and its number of contacts (distinct grains it touches, walls included). Walls get the
/// same sums over their own contacts.
struct GrainStress {
  std::vector<double> sxx, sxy, syx, syy;
  std::vector<std::int32_t> coordination;
};
GrainStress grain_stress(const Snapshot& s);

/// Whether each grain is a rattler: a free grain left with fewer than 2 contacts when
/// rattlers are removed one after another (each removal takes its contacts from its
/// neighbours, which may then become rattlers) until none is left. Walls never are.
std::vector<bool> find_rattlers(const Snapshot& s);

}  // namespace tridem
