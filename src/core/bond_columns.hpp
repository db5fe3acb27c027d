#pragma once
// The cohesive bonds' storage, one shape for every backend: a structure of columns whose
// Column is a host vector in CpuSolver and a DeviceBuffer in the CUDA solver, with the
// view physics::BondArrays the shared step rules read (physics/bond_step.hpp). The initial
// columns are built once on the host from the BondModel, in the solver's Real; the GPU
// uploads them. The snapshot's bond columns and the checkpoint's bond state are filled
// from host columns by the functions below, so both backends show and save bonds alike.
//
// C++17: the CUDA sources include it.
#include "core/bond_model.hpp"
#include "physics/bond_step.hpp"
#include "tridem/snapshot.hpp"
#include "tridem/solver_state.hpp"

#include <cmath>
#include <cstdint>
#include <vector>

namespace tridem {

template <class T>
using HostColumn = std::vector<T>;

template <template <class> class Column, class Real>
struct BondColumns {
  // Per bond (Scene::bonds order).
  Column<std::int32_t> a, b, material;
  Column<physics::BondGeometry<Real>> geometry;
  Column<Real> damage;  ///< kBondPoints per bond, bond-major
  Column<std::uint8_t> broken;
  Column<double> dissipated;                ///< J/m released so far
  Column<physics::BondForce<Real>> result;  ///< this step's
  // Per material.
  Column<physics::BondStrength<Real>> strength;
  // Per particle (first: n + 1) and per slot (two per bond).
  Column<std::int32_t> first, partner, bond_of;

  /// Every column beside the same column of `other` (another storage of this shape):
  /// f(mine, others, is_state), the state columns being those a step or a restart writes.
  template <class Other, class F>
  void for_each_column_with(Other& other, F&& f) {
    zip(*this, other, f);
  }
  template <class Other, class F>
  void for_each_column_with(Other& other, F&& f) const {
    zip(*this, other, f);
  }

  std::size_t size() const { return a.size(); }

  /// The view of these columns for `count` bonds (0: none, null pointers).
  physics::BondArrays<Real> view(std::size_t count) const {
    physics::BondArrays<Real> v;
    if (count == 0) return v;
    v.count = static_cast<std::int64_t>(count);
    v.a = a.data();
    v.b = b.data();
    v.material = material.data();
    v.geometry = geometry.data();
    v.strength = strength.data();
    v.first = first.data();
    v.partner = partner.data();
    v.bond_of = bond_of.data();
    // The view writes the state columns: the storage is the solver's, which owns both.
    v.damage = const_cast<Real*>(damage.data());
    v.broken = const_cast<std::uint8_t*>(broken.data());
    v.dissipated = const_cast<double*>(dissipated.data());
    v.result = const_cast<physics::BondForce<Real>*>(result.data());
    return v;
  }

 private:
  template <class Self, class Other, class F>
  static void zip(Self& s, Other& o, F& f) {
    f(s.a, o.a, false);
    f(s.b, o.b, false);
    f(s.material, o.material, false);
    f(s.geometry, o.geometry, false);
    f(s.strength, o.strength, false);
    f(s.first, o.first, false);
    f(s.partner, o.partner, false);
    f(s.bond_of, o.bond_of, false);
    f(s.damage, o.damage, true);
    f(s.broken, o.broken, true);
    f(s.dissipated, o.dissipated, true);
    f(s.result, o.result, true);
  }
};

template <class Real>
using HostBondColumns = BondColumns<HostColumn, Real>;

/// The columns of `m` at the start of a run, in Real: intact, undamaged, nothing released.
template <class Real>
HostBondColumns<Real> initial_bond_columns(const BondModel& m) {
  HostBondColumns<Real> c;
  if (m.size() == 0) return c;
  c.a = m.a;
  c.b = m.b;
  c.material = m.material;
  auto cast = [](Vec2d v) { return Vec2<Real>{static_cast<Real>(v.x), static_cast<Real>(v.y)}; };
  for (const physics::BondGeometry<double>& g : m.geometry) {
    physics::BondGeometry<Real> r{};
    for (int k = 0; k < physics::kBondPoints; ++k) {
      r.on_a[k] = cast(g.on_a[k]);
      r.on_b[k] = cast(g.on_b[k]);
    }
    r.normal = cast(g.normal);
    r.length = static_cast<Real>(g.length);
    r.stiffness = static_cast<Real>(g.stiffness);
    c.geometry.push_back(r);
  }
  for (const auto& s : m.strength) c.strength.push_back(physics::bond_strength_cast<Real>(s));
  c.first = m.first;
  c.partner = m.partner;
  c.bond_of = m.bond;
  c.damage.assign(m.size() * physics::kBondPoints, Real(0));
  c.broken.assign(m.size(), 0);
  c.dissipated.assign(m.size(), 0.0);
  c.result.assign(m.size(), physics::BondForce<Real>{});
  return c;
}

/// Bond k's damage as a snapshot shows it: the mean of its points' (`damage` bond-major,
/// kBondPoints per bond, as BondColumns::damage).
template <class Real>
double mean_bond_damage(const Real* damage, std::size_t k) {
  double mean = 0;
  for (int p = 0; p < physics::kBondPoints; ++p)
    mean += static_cast<double>(damage[k * physics::kBondPoints + p]) / physics::kBondPoints;
  return mean;
}

/// The snapshot's bond columns from host columns and the triangles' poses already in `out`:
/// each bond's mean damage, broken flag and the ends of its edge as carried by a (its two
/// Gauss points on a, extrapolated to 0 and 1 along the edge).
template <class Real>
void fill_bonds(Snapshot& out, const HostBondColumns<Real>& c) {
  const std::size_t nb = c.size();
  out.bond_a = c.a;
  out.bond_b = c.b;
  out.bond_broken = c.broken;
  for (auto* v : {&out.bond_damage, &out.bond_x0, &out.bond_y0, &out.bond_x1, &out.bond_y1})
    v->resize(nb);
  const double xi0 = physics::bond_point_position(0), xi1 = physics::bond_point_position(1);
  for (std::size_t k = 0; k < nb; ++k) {
    out.bond_damage[k] = mean_bond_damage(c.damage.data(), k);
    const auto a = static_cast<std::size_t>(c.a[k]);
    const physics::BondGeometry<Real>& g = c.geometry[k];
    const Vec2d p0{static_cast<double>(g.on_a[0].x), static_cast<double>(g.on_a[0].y)};
    const Vec2d p1{static_cast<double>(g.on_a[1].x), static_cast<double>(g.on_a[1].y)};
    const Vec2d centre{out.x[a], out.y[a]};
    const double cs = std::cos(out.theta[a]), sn = std::sin(out.theta[a]);
    const Vec2d e0 = centre + rotate(p0 + (p1 - p0) * (-xi0 / (xi1 - xi0)), cs, sn);
    const Vec2d e1 = centre + rotate(p0 + (p1 - p0) * ((1 - xi0) / (xi1 - xi0)), cs, sn);
    out.bond_x0[k] = e0.x;
    out.bond_y0[k] = e0.y;
    out.bond_x1[k] = e1.x;
    out.bond_y1[k] = e1.y;
  }
}

/// The checkpoint's bond state from host columns: each point's damage (Real, exact in
/// double) and the energy each bond released.
template <class Real>
void save_bonds(SolverState& out, const HostBondColumns<Real>& c) {
  out.bond_damage.assign(c.damage.begin(), c.damage.end());
  out.bond_dissipated = c.dissipated;
}

/// The state's bonds into host columns (validated first: sizes, damage in [0, 1]): damage
/// and energy as saved, broken where every point is fully damaged, no result until the
/// next step.
template <class Real>
void load_bonds(const SolverState& in, HostBondColumns<Real>& c, const std::string& source) {
  validate_bond_state(in, c.size(), source);
  for (std::size_t k = 0; k < c.size(); ++k) {
    bool broken = true;
    for (int p = 0; p < physics::kBondPoints; ++p) {
      const std::size_t at = k * physics::kBondPoints + static_cast<std::size_t>(p);
      c.damage[at] = static_cast<Real>(in.bond_damage[at]);
      broken = broken && in.bond_damage[at] >= 1;
    }
    c.broken[k] = broken ? 1 : 0;
    c.dissipated[k] = in.bond_dissipated[k];
    c.result[k] = physics::BondForce<Real>{};
  }
}

}  // namespace tridem
