#pragma once
// The solver's side of the energy budget in energy.csv (docs/output-format.md): what the
// state alone does not show. Kinetic and gravitational energy come from the snapshot.
//
// The balance users can check:
//   kinetic + potential + elastic + dissipated_damping + dissipated_friction
//     + dissipated_local + dissipated_fracture − wall_work = its value at step 0
// up to the time discretisation (docs/model.md, "Energy").

namespace tridem {

struct EnergyBudget {
  double elastic = 0;              ///< J/m stored in the contacts of the last step
  double dissipated_damping = 0;   ///< J/m removed by the normal dashpots since step 0
  double dissipated_friction = 0;  ///< J/m removed by Coulomb sliding since step 0
  double dissipated_local = 0;     ///< J/m removed by Cundall's local damping since step 0
  double wall_work = 0;            ///< J/m done on the grains by moving walls since step 0
  /// J/m released by the damage of cohesive bonds since step 0 (docs/fracture.md); the
  /// bonds' stored energy is in `elastic`.
  double dissipated_fracture = 0;
};

/// Indices of the four cumulative per-particle accumulators a solver keeps (the state
/// a restart needs, SolverState::energy).
enum EnergyAccumulator : int {
  kDissipatedDamping = 0,
  kDissipatedFriction = 1,
  kDissipatedLocal = 2,
  kWallWork = 3,
  kEnergyAccumulators = 4
};

/// The accumulators' names, in messages.
inline constexpr const char* kEnergyAccumulatorNames[kEnergyAccumulators] = {
    "dissipated damping energy", "dissipated friction energy",
    "dissipated local-damping energy", "wall work"};

}  // namespace tridem
