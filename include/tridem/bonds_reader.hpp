#pragma once
// Reading a frame's cohesive bonds back (docs/fracture.md), for `tridem render`'s cracks.
#include "tridem/snapshot.hpp"

#include <filesystem>

namespace tridem {

/// Reads back a bonds/bonds_STEP.vtp written by write_bonds_vtp into `s`'s bond arrays
/// (bond_a, bond_b, bond_damage, bond_broken and the edges' ends), in either encoding.
/// Throws Error on a file it cannot read or that is not such a line set.
void read_bonds_vtp(const std::filesystem::path& file, Snapshot& s);

}  // namespace tridem
