#include "core/memory_estimate.hpp"

#include "backends/cpu/partner_record.hpp"
#include "broadphase/candidate_pairs.hpp"
#include "core/particle_model.hpp"
#include "physics/cohesive_bond.hpp"
#include "physics/contact_force.hpp"
#include "physics/geometry.hpp"
#include "physics/pair_record.hpp"
#include "tridem/particle_fields.hpp"
#include "tridem/snapshot.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace tridem {

namespace {

/// Per particle, besides the fields: the CUDA broad phase's small flag, grid (cell keys
/// and indices, sorted: 4 words; 4 cells of start and end) and rows (new and old offsets,
/// reverse offsets, counts).
constexpr std::size_t kGpuListBytesPerParticle = 1 + 4 * 4 + 4 * 2 * 4 + 4 * 4;
/// The CPU's: cell bookkeeping (keys, order and the cell ranges), the row offsets of the
/// new and the old list, the reverse index's offsets and cursor, the row counts.
constexpr std::size_t kCpuListBytesPerParticle = 2 * 4 * 8 + 8 + 4 + 8 + 3 * 8 + 2 * 8;

template <class Real>
std::size_t gpu_bytes(std::size_t n, std::size_t pairs) {
  const std::size_t per_particle =
      bytes_per_particle<Real>([](auto f) { for_each_gpu_particle_field(f); }) +
      kGpuListBytesPerParticle;
  // Per pair: partner, slip, emitter, load and the reverse index's slot; and the memory
  // the phases of a step share (backends/cuda/slot_phases.cuh): the result's details
  // between builds, or while a list is built the old list, the slot ids, the reverse sort's
  // keys and CUB's scratch (keys and values), whichever is larger.
  const std::size_t build_phase =
      std::max<std::size_t>(4 + 4 + sizeof(physics::PairSlip<Real>), 4 + 4 + 8);
  const std::size_t per_pair = 4 + sizeof(physics::PairSlip<Real>) + 4 +
                               sizeof(physics::PairLoad<Real>) + 4 +
                               std::max(sizeof(physics::PairDetail<Real>), build_phase);
  // A frame's contact network, compacted on the GPU (backends/cuda/touching_pairs.cuh):
  // each particle's first row, and one window of rows (no more rows than a dense packing's
  // pairs can have: reserved_pairs).
  const std::size_t frame_scratch = 4 * (n + 1) + std::min(kContactRowsPerCopy, reserved_pairs(n)) *
                                                      sizeof(physics::TouchingPair<Real>);
  return n * per_particle + pairs * per_pair + frame_scratch + (16u << 20);
}

template <class Real>
std::size_t cpu_bytes(std::size_t n, std::size_t pairs) {
  const std::size_t per_particle =
      bytes_per_particle<Real>([](auto f) { for_each_particle_field(f); }) +
      kCpuListBytesPerParticle + sizeof(PartnerRecord<Real>);
  // Per pair: partner and slip twice (new and old list), the result and the reverse slot.
  const std::size_t per_pair =
      2 * (4 + sizeof(physics::PairSlip<Real>)) + sizeof(physics::PairForce<Real>) + 8;
  // Host copies: the scene's TriangleSpec, the particle model, a snapshot (its shown
  // fields, vertices, mass and inertia in double, material, motion) and about six contact
  // records of a dense packing.
  const std::size_t snapshot =
      8 * (Snapshot::kArraysPerParticle + 8) + sizeof(int) + sizeof(Motion);
  const std::size_t host = sizeof(TriangleSpec) + kParticleModelBytes + snapshot +
                           6 * sizeof(ContactRecord);
  return n * (per_particle + host) + pairs * per_pair;
}

/// The solver's bytes per bond, on either backend (core/bond_columns.hpp): a, b and
/// material, the geometry in Real, each point's damage, the broken flag, the released
/// energy (double), the step's result, and two list slots (partner, bond) per bond plus the
/// per-particle offsets (a bond is shared by two particles, and each particle with bonds has
/// at least one: one offset per bond is an upper bound).
template <class Real>
constexpr std::size_t solver_bond_bytes() {
  return 3 * 4 + sizeof(physics::BondGeometry<Real>) + physics::kBondPoints * sizeof(Real) + 1 + 8 +
         sizeof(physics::BondForce<Real>) + 2 * 2 * 4 + 4;
}

template <class Real>
std::size_t bond_bytes() {
  const std::size_t solver = solver_bond_bytes<Real>();
  // The host's: the scene's BondSpec, the bond model (a, b, material, geometry in double,
  // its slots) and the snapshot's line (a, b, damage, broken, two ends).
  const std::size_t host = sizeof(BondSpec) + 3 * 4 + sizeof(physics::BondGeometry<double>) +
                           2 * 2 * 4 + 4 + (2 * 4 + 8 + 1 + 4 * 8);
  return solver + host;
}

}  // namespace

std::size_t cpu_bond_bytes(Precision precision) {
  return precision == Precision::Float ? bond_bytes<float>() : bond_bytes<double>();
}

std::size_t gpu_bond_bytes(Precision precision) {
  // The GPU's columns, plus the double of each bond's elastic energy that energy() sums.
  return (precision == Precision::Float ? solver_bond_bytes<float>()
                                        : solver_bond_bytes<double>()) +
         8;
}

std::string mebibytes(std::size_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0f MiB", static_cast<double>(bytes) / (1024.0 * 1024.0));
  return text;
}

std::size_t gpu_pair_bytes(Precision precision) {
  return gpu_solver_bytes(0, 1, precision) - gpu_solver_bytes(0, 0, precision);
}

std::size_t first_list_pairs(const Scene& scene, const ParticleModel& model) {
  const std::size_t n = model.size();
  if (n < 2) return 0;
  const GridClasses classes = classify_for_grid(model.longest_edge, model.motion);
  const double margin = scene.simulation.skin * classes.cell;
  std::vector<double> lo_x(n), lo_y(n), hi_x(n), hi_y(n), x(n), y(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = model.centroid[i].x;
    y[i] = model.centroid[i].y;
    const physics::Aabb<double> box =
        physics::bounding_box(physics::place(model.centroid[i], 0.0, model.offsets[i].data()));
    lo_x[i] = box.lo.x - margin;
    lo_y[i] = box.lo.y - margin;
    hi_x[i] = box.hi.x + margin;
    hi_y[i] = box.hi.y + margin;
  }
  CandidatePairs<double> grid(model.longest_edge, model.motion);
  PairList pairs;
  const BoxArrays<double> boxes{lo_x.data(), lo_y.data(), hi_x.data(), hi_y.data()};
  // Every method's candidates are these pairs; the grid finds them in O(n).
  if (scene.simulation.periodic.any()) {
    const PeriodicView view{periodic_frame_of(scene.simulation.periodic, 0.0), x.data(), y.data()};
    grid.find(boxes, Method::Grid, true, pairs, &view);
  } else {
    grid.find(boxes, Method::Grid, true, pairs);
  }
  return static_cast<std::size_t>(pairs.count());
}

std::size_t gpu_solver_bytes(std::size_t n, std::size_t pairs, Precision precision,
                             std::size_t bonds) {
  return (precision == Precision::Float ? gpu_bytes<float>(n, pairs)
                                        : gpu_bytes<double>(n, pairs)) +
         bonds * gpu_bond_bytes(precision);
}

std::size_t cpu_run_bytes(std::size_t n, std::size_t pairs, Precision precision,
                          std::size_t bonds) {
  return (precision == Precision::Float ? cpu_bytes<float>(n, pairs)
                                        : cpu_bytes<double>(n, pairs)) +
         bonds * cpu_bond_bytes(precision);
}

}  // namespace tridem
