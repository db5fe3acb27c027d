#pragma once
// The rules of a step of the cohesive bonds (docs/fracture.md), written once for every
// backend: which bond acts (an intact one, on its own two triangles), its force and torques
// on both from the shared traction law (cohesive_bond.hpp), the order in which a particle
// adds its bonds' loads after its pairs' (its bonds ascending), and what the step leaves
// (damage, broken for good, the energy released). BondArrays is the view of the bond
// columns (core/bond_columns.hpp) that the CPU solver's loops and the CUDA kernels receive:
// the backends only load, store and loop.
#include "physics/cohesive_bond.hpp"
#include "tridem/hd.hpp"
#include "tridem/vec2.hpp"

#include <cstdint>

namespace tridem::physics {

/// The bonds as pointers into one solver's columns (host or device): per bond its two
/// triangles, material, geometry, the damage of its points (kBondPoints per bond,
/// bond-major), whether it broke, the energy it released so far (J/m, cumulative) and this
/// step's result; per material the strengths; per particle its bonds, slots
/// [first[i], first[i + 1]) of partner and bond_of, bonds ascending. count 0 and null
/// pointers without bonds.
template <class Real>
struct BondArrays {
  std::int64_t count = 0;
  const std::int32_t* a = nullptr;
  const std::int32_t* b = nullptr;
  const std::int32_t* material = nullptr;
  const BondGeometry<Real>* geometry = nullptr;
  const BondStrength<Real>* strength = nullptr;
  const std::int32_t* first = nullptr;
  const std::int32_t* partner = nullptr;
  const std::int32_t* bond_of = nullptr;
  Real* damage = nullptr;
  std::uint8_t* broken = nullptr;
  double* dissipated = nullptr;
  BondForce<Real>* result = nullptr;
};

/// Bond k's force this step (zero once broken: the contact law takes over), b's centroid
/// given in the frame of a's centroid (`b_from_a`, the caller's offset rule: the pair's,
/// physics/local_frame.hpp, or a periodic image's) and the two angles.
template <class Real>
TRIDEM_HD inline BondForce<Real> step_bond(const BondArrays<Real>& v, std::int64_t k,
                                           Vec2<Real> b_from_a, double theta_a, double theta_b) {
  if (v.broken[k] != 0) return BondForce<Real>{};
  const BondSide<Real> a{{Real(0), Real(0)}, theta_a};
  const BondSide<Real> b{b_from_a, theta_b};
  return bond_force(a, b, v.geometry[k], v.strength[v.material[k]], v.damage + k * kBondPoints);
}

/// Adds particle p's bond loads (this step's results) to its pairs' sum f, t: its bonds in
/// ascending order, a's share or b's by which end p is. Both backends sum in this order,
/// so that the loads agree to rounding and OpenMP equals serial.
template <class Real>
TRIDEM_HD inline void add_bond_loads(const BondArrays<Real>& v, std::int64_t p, Vec2<Real>& f,
                                     Real& t) {
  for (std::int32_t s = v.first[p]; s < v.first[p + 1]; ++s) {
    const std::int32_t k = v.bond_of[s];
    const BondForce<Real>& r = v.result[k];
    if (v.a[k] == p) {
      f.x += r.force_a.x;
      f.y += r.force_a.y;
      t += r.torque_a;
    } else {
      f.x -= r.force_a.x;
      f.y -= r.force_a.y;
      t += r.torque_b;
    }
  }
}

/// Writes what bond k's step leaves, once the step is accepted: its points' damage, broken
/// for good when all are fully damaged (never again computed), the energy released.
template <class Real>
TRIDEM_HD inline void commit_bond(const BondArrays<Real>& v, std::int64_t k) {
  if (v.broken[k] != 0) return;
  const BondForce<Real>& r = v.result[k];
  TRIDEM_UNROLL
  for (int p = 0; p < kBondPoints; ++p) v.damage[k * kBondPoints + p] = r.damage[p];
  v.broken[k] = r.broken ? 1 : 0;
  v.dissipated[k] += static_cast<double>(r.dissipated);
}

/// True when triangles i and j hold an intact bond (the pair gets no contact force and no
/// history); false without bonds.
template <class Real>
TRIDEM_HD inline bool intact_bond_between(const BondArrays<Real>& v, std::int64_t i,
                                          std::int64_t j) {
  return intact_bond_between(v.first, v.partner, v.bond_of, v.broken, i, j);
}

}  // namespace tridem::physics
