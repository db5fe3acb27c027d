#pragma once
// The per-step logs: their headers are a contract with users' scripts (see
// docs/output-format.md), so they live here once.
#include "io/output/out_file.hpp"
#include "tridem/output.hpp"

#include <string_view>

namespace tridem::io {

inline constexpr std::string_view kEnergyHeader =
    "step,time,kinetic,momentum_x,momentum_y,angular_momentum,potential,elastic,"
    "dissipated_damping,dissipated_friction,dissipated_local,wall_work,total\n";
inline constexpr std::string_view kWallsHeader = "step,time,id,fx,fy,torque\n";

void write_energy_row(OutFile&, const EnergyRow&);

/// One row per fixed or prescribed particle: the contact force and torque on it.
void write_wall_rows(OutFile&, const Snapshot&);

}  // namespace tridem::io
