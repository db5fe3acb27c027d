#pragma once
// The one memory estimate of a run: per-particle bytes counted from the field lists of
// tridem/particle_fields.hpp, per-pair bytes from the pair-slot types, and the one rule for
// the pair slots a solver reserves at start. The CUDA solver refuses a scene that does not
// fit with it; `tridem info` prints it for both kinds of backend.
#include "tridem/scene.hpp"

#include <cstddef>
#include <string>

namespace tridem {

struct ParticleModel;

/// Pair slots the CPU solvers reserve (address space, not memory: a vector's pages are only
/// touched as the list fills them) before they have seen the scene's contacts: a dense
/// packing lists 6.6 candidate pairs per particle (bench/), and a floor covers small scenes.
inline constexpr std::size_t kReservedPairsPerParticle = 10;
inline constexpr std::size_t reserved_pairs(std::size_t n) {
  return kReservedPairsPerParticle * n + 1024;
}

/// The pair slots a list of `listed` pairs is given on the GPU, where slots are memory: its
/// first list's count and a fifth more, so that a packing that densifies a little does not
/// allocate again, and a floor for small scenes.
inline constexpr std::size_t pair_slots_for(std::size_t listed) {
  return listed + listed / 5 + 1024;
}

/// Rows of a frame's contact network that the CUDA solver compacts and downloads at a time
/// (backends/cuda/touching_pairs.cuh): the GPU scratch a frame takes beside the solver's
/// arrays is this many rows at most, 168 MB in float, not one row for every touching pair
/// (24 GB at 10^8 triangles in a dense pile).
inline constexpr std::size_t kContactRowsPerCopy = std::size_t{1} << 22;

/// About how many pairs the first list of a run of `model` holds: the particles whose
/// bounding boxes, widened by the skin the GPU's list keeps, overlap (the broad phase's
/// candidates; the contact test drops some). What `tridem info` sizes the pair slots by.
std::size_t first_list_pairs(const Scene& scene, const ParticleModel& model);

/// `bytes` as the refusals print it ("123 MiB").
std::string mebibytes(std::size_t bytes);

/// Bytes of GPU memory one pair slot takes (the per-pair part of gpu_solver_bytes).
std::size_t gpu_pair_bytes(Precision precision);

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
