#pragma once
// The checkpoint file, version 7. All numbers little-endian; reals are IEEE doubles.
//
//   header (48 bytes)
//     0  char[8]  magic "TRIDEMCK"
//     8  u32      version (7; 6 had no particle order, and is still read as a state
//                  in the order the scene gives; 5 had no bonds, and is still read as a
//                  state without bonds; 4 had no bodies, and is still read as a state without
//                  bodies; 3 stored six edge slips per pair, 2 also no energy sums,
//                  1 also no settings)
//    12  u32      precision of the solver: 0 double, 1 float
//    16  u64      particle count n
//    24  u64      scene fingerprint (scene_fingerprint)
//    32  u64      payload size in bytes
//    40  u32      CRC-32 of the payload
//    44  u32      CRC-32 of header bytes 0..43
//   payload
//     i64 step, f64 time
//     u32 k, then k physics settings (physics_settings()), each as two texts, key and
//       value; a text is a u32 byte count and that many bytes of UTF-8
//     f64[n] x, y, theta, vx, vy, omega (six arrays, in this order)
//     f64[n] dissipated damping, friction, local damping, wall work (four arrays: the
//            energy budget's cumulative per-particle sums, SolverState::energy)
//     u64 b, the number of bodies of several triangles (0 without; absent in version 4)
//     f64[b] body x, y, theta, vx, vy, omega (six arrays: SolverState::body_x, ...)
//     u64 c, the number of cohesive bonds (0 without; absent before version 6)
//     f64[2c] their points' damage (bond-major), f64[c] the energy each released
//     u64 t, then i32[t] the order the solver stepped the particles in, when it numbered
//            them by place again mid-run (SolverState::particle_order; t is 0 or n)
//     u64 q, then i32[q] its bodies' order (SolverState::body_order; 0 or b)
//            (t, q and their entries absent before version 7)
//     u64 m, the number of pairs with contact history
//     i32[m] emitters, i32[m] partners, f64[2m] tangential spring states u = √k_t·ξ
//            (x, y per pair, pair-major)
//
// The header has its own checksum so that a damaged count is caught before it is used
// to size anything; the payload size is checked against the file size for the same
// reason. Bump the version on any change to this layout (version 1 had no physics
// settings, version 2 no energy arrays, version 3 six edge slips per pair, version 4 no
// bodies, version 5 no bonds, version 6 no particle order).
#include "tridem/solver_state.hpp"

#include <cstddef>
#include <cstdint>

namespace tridem::checkpoint_format {

inline constexpr char kMagic[8] = {'T', 'R', 'I', 'D', 'E', 'M', 'C', 'K'};
inline constexpr std::uint32_t kVersion = 7;
/// The oldest version read: 4, the same layout without the bodies' block.
inline constexpr std::uint32_t kOldestReadVersion = 4;
/// The first version with the bodies' block.
inline constexpr std::uint32_t kBodiesVersion = 5;
/// The first version with the bonds' block.
inline constexpr std::uint32_t kBondsVersion = 6;
/// The first version with the particle order's block.
inline constexpr std::uint32_t kOrderVersion = 7;
/// Bytes of one bond's state: its points' damage and its released energy.
inline constexpr std::size_t kBytesPerBond = 8 * (SolverState::kBondStatePoints + 1);
inline constexpr std::size_t kHeaderSize = 48;
inline constexpr std::size_t kHeaderCrcOffset = 44;
inline constexpr std::size_t kPayloadCrcOffset = 40;
/// Per-particle arrays: SolverState's fields (particle_fields.hpp), six of state, four of
/// energy in this version. A field added to the State or Sum lists changes the layout:
/// bump kVersion, and keep reading the older version.
inline constexpr std::size_t kArraysPerParticle = SolverState::kArraysPerParticle;
static_assert(kVersion != 7 || kArraysPerParticle == 10,
              "the checkpointed fields changed: bump the checkpoint format version");
inline constexpr std::size_t kBytesPerParticle = 8 * kArraysPerParticle;
/// Per-body arrays: SolverState's body fields (body_fields.hpp), six of state.
inline constexpr std::size_t kArraysPerBody = SolverState::kArraysPerBody;
static_assert(kVersion != 7 || kArraysPerBody == 6,
              "the checkpointed body fields changed: bump the checkpoint format version");
inline constexpr std::size_t kBytesPerBody = 8 * kArraysPerBody;
/// The least bytes of a payload of n particles in `version`: step, time, the settings
/// count, the per-particle arrays, b (from version 5), c (from version 6), t and q (from
/// version 7), m.
inline constexpr std::size_t fixed_payload_size(std::uint64_t n, std::uint32_t version = kVersion) {
  return 8 + 8 + 4 + kBytesPerParticle * n + (version >= kBodiesVersion ? 8 : 0) +
         (version >= kBondsVersion ? 8 : 0) + (version >= kOrderVersion ? 16 : 0) + 8;
}
inline constexpr std::size_t kBytesPerPair = SolverState::kBytesPerPair;
static_assert(kVersion != 7 || kBytesPerPair == 4 + 4 + 2 * 8,
              "the contact history's fields changed: bump the checkpoint format version");

}  // namespace tridem::checkpoint_format
