#pragma once
// A PairForce split by who reads it. Every step reads a pair's load: the gather sums its
// force and torques and the energy rows add its dissipations. Only output reads the rest
// (contact point, normal, depth, stored energy, flags). The GPU keeps the two in separate
// arrays and writes the detail on the steps whose results are read (the last step of each
// advance() call): a step then moves 48 of 104 bytes per pair in double, 24 of 52 in float.
#include "physics/contact_force.hpp"

namespace tridem::physics {

template <class Real>
struct PairLoad {
  Vec2<Real> force_a{};
  Real torque_a = 0;
  Real torque_b = 0;
  Real damping_dissipation = 0;
  Real friction_dissipation = 0;
};

template <class Real>
struct PairDetail {
  Vec2<Real> point{};
  Real depth = 0;
  Real elastic_energy = 0;
  Vec2<Real> normal{};
  bool touching = false;
  bool sliding = false;
};

/// What a contact record takes from one touching pair, and nothing more (40 bytes in
/// float, 72 in double, against 60 and 112 of the pair's whole result): its two particles,
/// the force on the emitter, the point (relative to the emitter's centroid), the normal,
/// the depth and whether it slid. The rows a frame's contact network is downloaded as
/// (backends/cuda/touching_pairs.cuh).
template <class Real>
struct TouchingPair {
  int emitter;
  int partner;
  Vec2<Real> force;
  Vec2<Real> point;
  Vec2<Real> normal;
  Real depth;
  int sliding;
};

template <class Real>
TRIDEM_HD inline PairLoad<Real> load_of(const PairForce<Real>& r) {
  return {r.force_a, r.torque_a, r.torque_b, r.damping_dissipation, r.friction_dissipation};
}

template <class Real>
TRIDEM_HD inline PairDetail<Real> detail_of(const PairForce<Real>& r) {
  return {r.point, r.depth, r.elastic_energy, r.normal, r.touching, r.sliding};
}

/// The PairForce the two parts were taken from.
template <class Real>
TRIDEM_HD inline PairForce<Real> joined(const PairLoad<Real>& l, const PairDetail<Real>& d) {
  PairForce<Real> r;
  r.force_a = l.force_a;
  r.torque_a = l.torque_a;
  r.torque_b = l.torque_b;
  r.point = d.point;
  r.depth = d.depth;
  r.elastic_energy = d.elastic_energy;
  r.damping_dissipation = l.damping_dissipation;
  r.friction_dissipation = l.friction_dissipation;
  r.normal = d.normal;
  r.touching = d.touching;
  r.sliding = d.sliding;
  return r;
}

}  // namespace tridem::physics
