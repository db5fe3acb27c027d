#pragma once
// The one memory estimate of a run: per-particle bytes counted from the field lists of
// tridem/particle_fields.hpp, per-pair bytes from the pair-slot types, and the one rule for
// the pair slots a solver reserves at start. The CUDA solver refuses a scene that does not
// fit with it; `tridem info` prints it for both kinds of backend.
#include "tridem/scene.hpp"

#include <cstddef>

namespace tridem {

/// Pair slots every solver reserves before it has seen the scene's contacts: a dense
/// packing lists 6.6 candidate pairs per particle (bench/), the GPU's Verlet skin adds
/// more, and a floor covers small scenes. A list grows past it only when a scene packs
/// denser.
inline constexpr std::size_t kReservedPairsPerParticle = 10;
inline constexpr std::size_t reserved_pairs(std::size_t n) {
  return kReservedPairsPerParticle * n + 1024;
}

/// Bytes of GPU memory the CUDA solver allocates for n particles, room for `pairs` pairs
/// and `bonds` cohesive bonds (sized once at start).
std::size_t gpu_solver_bytes(std::size_t n, std::size_t pairs, Precision precision,
                             std::size_t bonds = 0);

/// Of those, the bytes of one cohesive bond on the GPU: the columns of core/bond_columns.hpp
/// and the energy scratch.
std::size_t gpu_bond_bytes(Precision precision);

/// Bytes of host memory a run on the CPU backends holds for n particles, room for `pairs`
/// pairs and `bonds` cohesive bonds: the solver and the host copies (scene, model,
/// snapshot).
std::size_t cpu_run_bytes(std::size_t n, std::size_t pairs, Precision precision,
                          std::size_t bonds = 0);

/// Of those, the bytes of one cohesive bond (docs/fracture.md): the solver's geometry,
/// damage, result and lists, the host's bond spec and model, the snapshot's line.
std::size_t cpu_bond_bytes(Precision precision);

}  // namespace tridem
