#pragma once
// The bonded specimen of the bond parity and restart tests: the Brazilian disc's granite
// (support/brazilian_disc.hpp) on a coarse mesh, its top platen driven down fast enough
// that bonds are damaged and broken within the tests' few hundred steps (the validation
// test's 0.1 m/s needs tens of thousands). Gmsh meshes it: without Gmsh the scene throws
// SceneError and the tests skip.
#include "support/brazilian_disc.hpp"
#include "tridem/error.hpp"

namespace tridem::test {

/// Steps after which the loaded disc has damaged bonds (checked by
/// Bonds.LoadedDiscIsDamagedWithinTheParitySteps) and broken ones by kLoadedDiscSteps.
constexpr std::int64_t kLoadedDiscDamagedBy = 300;
constexpr std::int64_t kLoadedDiscSteps = 600;

/// 5 mm elements (some 180 triangles), the top platen at `speed` m/s.
inline Scene loaded_bonded_disc(double speed = 5) { return brazilian_scene(0.005, speed); }

/// loaded_bonded_disc(), or an empty scene and `skip` set in a build without Gmsh.
inline Scene loaded_bonded_disc_or_skip(bool& skip) {
  try {
    return loaded_bonded_disc();
  } catch (const SceneError&) {
    skip = true;
    return {};
  }
}

/// Bonds with some damage, and broken ones, of a state.
struct BondCount {
  std::size_t damaged = 0, broken = 0;
};
inline BondCount count_bonds(const SolverState& s) {
  BondCount c;
  for (std::size_t k = 0; k < s.bonds(); ++k) {
    const double d0 = s.bond_damage[2 * k], d1 = s.bond_damage[2 * k + 1];
    c.damaged += d0 > 0 || d1 > 0;
    c.broken += d0 == 1 && d1 == 1;
  }
  return c;
}

}  // namespace tridem::test
