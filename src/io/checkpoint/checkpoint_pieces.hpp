#pragma once
// A checkpoint file (format.hpp) in pieces, so that several writers can make one file side
// by side (the MPI ranks: mpi/parallel_checkpoint.hpp). Each writer holds a contiguous
// slice of every numbering: particles and bodies by id, bonds by index, pairs in
// (emitter, partner) order. It encodes its slice of each array at the array's place in the
// file, and the pieces' checksums combine into the payload's. encode_checkpoint is the
// case of one writer holding one slice of everything, so that both make the same bytes.
#include "tridem/checkpoint.hpp"

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace tridem::checkpoint_pieces {

/// How many particles, bodies of several triangles, bonds and pairs with history: a file's
/// totals, or the first of each in a slice.
struct Counts {
  std::uint64_t particles = 0, bodies = 0, bonds = 0, pairs = 0;
  /// Entries of the particle order's block and of the bodies' (0 or all: one writer holds
  /// the order whole, at the start of the slice that counts).
  std::uint64_t ordered = 0, ordered_bodies = 0;
};

/// Receives a piece: its bytes, to go at `offset` in the payload (after the header).
using Emit = std::function<void(std::uint64_t offset, std::span<const std::uint8_t> bytes)>;

/// The payload's opening: the step, the time and the physics settings.
std::vector<std::uint8_t> encode_opening(const CheckpointMeta& meta, std::int64_t step,
                                         double time);

/// The payload's size in bytes, from its opening's and the file's totals.
std::uint64_t payload_size(std::uint64_t opening_size, const Counts& total);

/// Emits the pieces of `slice`, a SolverState of the slice's particles, bodies, bonds and
/// pairs only (its energy arrays may be empty: zeros), which are those of the whole state
/// numbered from `first`; the file's totals are `total`, its opening `opening_size` bytes.
/// With `counts`, also the blocks' counts (bodies, bonds, pairs), which one writer emits.
/// Throws an internal error for a slice that does not fit the totals.
void encode_slice(const SolverState& slice, const Counts& first, const Counts& total,
                  std::uint64_t opening_size, bool counts, const Emit& emit);

/// The file's header: the payload's size and checksum, and the header's own.
std::vector<std::uint8_t> encode_header(const CheckpointMeta& meta, std::uint64_t particles,
                                        std::uint64_t payload_size, std::uint32_t payload_crc);

/// Where a piece lies in the payload, and its CRC-32.
struct PieceSum {
  std::uint64_t offset = 0, size = 0;
  std::uint32_t crc = 0;
};

/// The payload's CRC-32 from those of its pieces, in any order (empty ones are skipped).
/// Throws an internal error unless the pieces cover [0, payload_size) once each.
std::uint32_t combine(std::vector<PieceSum> pieces, std::uint64_t payload_size);

}  // namespace tridem::checkpoint_pieces
