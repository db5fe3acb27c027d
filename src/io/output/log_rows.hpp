#pragma once
// The per-step logs: their headers are a contract with users' scripts (see
// docs/output-format.md), so they live here once.
#include "io/output/out_file.hpp"
#include "tridem/measurements.hpp"
#include "tridem/output.hpp"

#include <string_view>

namespace tridem::io {

inline constexpr std::string_view kEnergyHeader =
    "step,time,kinetic,momentum_x,momentum_y,angular_momentum,potential,elastic,"
    "dissipated_damping,dissipated_friction,dissipated_local,wall_work,total,dissipated_fracture\n";
// walls.csv: x, y, vx, vy (the wall's centroid and velocity, issue 15's strains) came after
// torque; columns are only ever added at the end.
inline constexpr std::string_view kWallsHeader = "step,time,id,fx,fy,torque,x,y,vx,vy\n";
inline constexpr std::string_view kBondsHeader =
    "step,time,intact,damaged,broken,fracture_energy\n";

/// A [[measure]]'s file (tridem/measurements.hpp's Measurement, in its order).
inline constexpr std::string_view kMeasureHeader =
    "step,time,area,particles,contacts,rattlers,sxx,sxy,syx,syy,pressure,deviatoric,"
    "packing_fraction,coordination,mechanical_coordination,fabric_xx,fabric_xy,fabric_yy,"
    "mean_overlap,max_overlap\n";

void write_energy_row(OutFile&, const EnergyRow&);

void write_measure_row(OutFile&, const Measurement&);

/// One row per fixed or prescribed particle: the contact force and torque on it, then its
/// centroid and velocity (where a servo or programmed wall is: a sample's strain).
void write_wall_rows(OutFile&, const Snapshot&);

/// bonds.csv's row: the bonds intact (no damage), damaged (some, not broken) and broken,
/// and the energy their damage released since step 0 (EnergyBudget::dissipated_fracture).
void write_bond_row(OutFile&, const Snapshot&, double fracture_energy);

}  // namespace tridem::io
