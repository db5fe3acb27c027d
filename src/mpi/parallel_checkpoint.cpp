// The ranks' checkpoint, written side by side (docs/scaling.md, "Checkpoints"): the same
// file, byte for byte, as one rank writes, without a rank holding the whole state.
#include "io/checkpoint/checkpoint_pieces.hpp"
#include "io/checkpoint/crc32.hpp"
#include "io/checkpoint/format.hpp"
#include "mpi/agreement.hpp"
#include "mpi/collectives.hpp"
#include "mpi/mpi_solver.hpp"
#include "mpi/shared_file.hpp"
#include "tridem/error.hpp"

#include <algorithm>
#include <chrono>
#include <exception>
#include <fmt/format.h>
#include <optional>
#include <tuple>
#include <type_traits>
#include <utility>

namespace tridem::mpi {

namespace {

using checkpoint_pieces::Counts;

/// The first item of rank r's slice of `total` items (r = ranks: the end).
std::uint64_t slice_start(std::uint64_t total, int r, int ranks) {
  return total * static_cast<std::uint64_t>(r) / static_cast<std::uint64_t>(ranks);
}

/// The rank whose slice of `total` items holds item g.
int slice_of(std::uint64_t g, std::uint64_t total, int ranks) {
  if (total == 0) return 0;
  int r = static_cast<int>(g * static_cast<std::uint64_t>(ranks) / total);
  while (slice_start(total, r + 1, ranks) <= g) ++r;  // integer division's rounding
  while (slice_start(total, r, ranks) > g) --r;
  return r;
}

/// Runs `f`, then every rank throws the lowest failing rank's message, if any failed.
template <class F>
void agreed(MPI_Comm comm, F&& f) {
  std::optional<std::string> problem;
  try {
    f();
  } catch (const std::exception& e) {
    problem = e.what();
  }
  if (auto message = agree(comm, problem)) throw RunError(*message);
}

/// Places item g (of the slice from `first`, `count` items) once.
std::size_t place(double id, std::uint64_t first, std::uint64_t count,
                  std::vector<std::uint8_t>& seen, const char* what) {
  const auto g = static_cast<std::uint64_t>(as_id(id));
  if (g < first || g >= first + count || seen[g - first] != 0)
    throw RunError(fmt::format("internal error: {} {} sent to the checkpoint slice from {} "
                               "({} of them) twice or to the wrong rank",
                               what, g, first, count));
  seen[g - first] = 1;
  return static_cast<std::size_t>(g - first);
}

void expect_all(const std::vector<std::uint8_t>& seen, const char* what) {
  if (std::find(seen.begin(), seen.end(), 0) != seen.end())
    throw RunError(fmt::format("internal error: a checkpoint slice misses some of its {}", what));
}

}  // namespace

template <class Real>
void MpiSolver<Real>::save_checkpoint(const std::filesystem::path& file, const CheckpointMeta& meta,
                                      Checkpoint& /*scratch: each rank uses its own*/) const {
  order(kCheckpoint, 0);
  write_checkpoint_part(&file, &meta);
}

template <class Real>
void MpiSolver<Real>::write_checkpoint_part(const std::filesystem::path* file,
                                            const CheckpointMeta* meta) const {
  const auto start = std::chrono::steady_clock::now();
  std::string path = rank_ == 0 ? file->string() : std::string();
  broadcast(comm_, path, 0);
  Counts total{n_, model_.bodies.size(), scene_.bonds.size(), 0};
  Counts first{slice_start(total.particles, rank_, ranks_),
               slice_start(total.bodies, rank_, ranks_), slice_start(total.bonds, rank_, ranks_),
               0};
  const Counts count{slice_start(total.particles, rank_ + 1, ranks_) - first.particles,
                     slice_start(total.bodies, rank_ + 1, ranks_) - first.bodies,
                     slice_start(total.bonds, rank_ + 1, ranks_) - first.bonds, 0};
  constexpr std::size_t kPoints = SolverState::kBondStatePoints;

  // What this rank reports, each record to the rank whose slice holds it: a particle's,
  // body's and bond's by its id, a pair's by its emitter's.
  std::vector<std::vector<double>> particles(static_cast<std::size_t>(ranks_)),
      pairs(particles.size()), bodies(particles.size()), bonds(particles.size());
  SolverState& ls = scratch_state_;
  agreed(comm_, [&] {
    local_->solver().save_state(ls);
    const Reported own = reported(ls);
    for (std::size_t k : own.particles)
      pack_particle(particles[static_cast<std::size_t>(
                        slice_of(static_cast<std::uint64_t>(global_[k]), total.particles, ranks_))],
                    ls, k);
    for (std::size_t p : own.pairs)
      pack_pair(
          pairs[static_cast<std::size_t>(slice_of(
              static_cast<std::uint64_t>(global_[static_cast<std::size_t>(ls.pair_emitter[p])]),
              total.particles, ranks_))],
          ls, p);
    for (std::size_t b : own.bodies)
      pack_body(bodies[static_cast<std::size_t>(
                    slice_of(static_cast<std::uint64_t>(global_body_[b]), total.bodies, ranks_))],
                ls, b);
    for (std::size_t k : own.bonds)
      pack_bond(bonds[static_cast<std::size_t>(
                    slice_of(static_cast<std::uint64_t>(global_bond_[k]), total.bonds, ranks_))],
                ls, k);
  });
  const std::vector<double> got_particles = send_each(comm_, particles),
                            got_pairs = send_each(comm_, pairs),
                            got_bodies = send_each(comm_, bodies),
                            got_bonds = send_each(comm_, bonds);
  particles = pairs = bodies = bonds = {};

  // This rank's slice, as a SolverState of its items only.
  SolverState part;
  part.step = ls.step;
  part.time = ls.time;
  agreed(comm_, [&] {
    std::vector<std::uint8_t> seen(count.particles, 0);
    SolverState::for_each_field([&](auto field) {
      for_each_array(part.column(field),
                     [&](std::vector<double>& v, int) { v.assign(count.particles, 0.0); });
    });
    for (std::size_t at = 0; at < got_particles.size();) {
      const std::size_t i =
          place(got_particles[at++], first.particles, count.particles, seen, "particle");
      SolverState::for_each_field([&](auto field) {
        for_each_array(part.column(field),
                       [&](std::vector<double>& v, int) { v[i] = got_particles[at++]; });
      });
    }
    expect_all(seen, "particles");
    std::vector<PairRecord> history;
    for (std::size_t at = 0; at < got_pairs.size();) history.push_back(read_pair(got_pairs, at));
    append_sorted(history, part);
    seen.assign(count.bodies, 0);
    SolverState::for_each_body_column(
        [&](auto field) { part.column(field).assign(count.bodies, 0.0); });
    for (std::size_t at = 0; at < got_bodies.size();) {
      const std::size_t b = place(got_bodies[at++], first.bodies, count.bodies, seen, "body");
      SolverState::for_each_body_column(
          [&](auto field) { part.column(field)[b] = got_bodies[at++]; });
    }
    expect_all(seen, "bodies");
    seen.assign(count.bonds, 0);
    part.bond_damage.assign(kPoints * count.bonds, 0.0);
    part.bond_dissipated.assign(count.bonds, 0.0);
    for (std::size_t at = 0; at < got_bonds.size();) {
      const std::size_t k = place(got_bonds[at++], first.bonds, count.bonds, seen, "bond");
      for (std::size_t q = 0; q < kPoints; ++q) part.bond_damage[kPoints * k + q] = got_bonds[at++];
      part.bond_dissipated[k] = got_bonds[at++];
    }
    expect_all(seen, "bonds");
  });

  // The pairs' slices follow each other in rank order, as the emitters' do.
  unsigned long long mine = part.pairs(), before = 0, all = 0;
  MPI_Exscan(&mine, &before, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm_);
  MPI_Allreduce(&mine, &all, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm_);
  first.pairs = rank_ == 0 ? 0 : before;  // MPI_Exscan leaves rank 0's undefined
  total.pairs = all;

  // Rank 0 writes the payload's opening (step, time, settings) and the blocks' counts.
  std::vector<std::uint8_t> opening;
  if (rank_ == 0) opening = checkpoint_pieces::encode_opening(*meta, part.step, part.time);
  unsigned long long opening_size = opening.size();
  MPI_Bcast(&opening_size, 1, MPI_UNSIGNED_LONG_LONG, 0, comm_);
  const std::uint64_t payload = checkpoint_pieces::payload_size(opening_size, total);
  std::vector<std::pair<std::uint64_t, std::vector<std::uint8_t>>> pieces;
  std::vector<double> sums;  // offset, size, CRC-32 of each piece
  agreed(comm_, [&] {
    if (rank_ == 0) pieces.emplace_back(0, std::move(opening));
    checkpoint_pieces::encode_slice(
        part, first, total, opening_size, rank_ == 0,
        [&](std::uint64_t offset, std::span<const std::uint8_t> bytes) {
          pieces.emplace_back(offset, std::vector<std::uint8_t>(bytes.begin(), bytes.end()));
        });
    for (const auto& [offset, bytes] : pieces) {
      sums.push_back(static_cast<double>(offset));
      sums.push_back(static_cast<double>(bytes.size()));
      sums.push_back(static_cast<double>(io::crc32(bytes)));
    }
  });
  part = SolverState{};
  const std::vector<double> every_sum = collect(comm_, sums, false);
  std::vector<std::uint8_t> header;
  agreed(comm_, [&] {
    if (rank_ != 0) return;
    std::vector<checkpoint_pieces::PieceSum> each;
    for (std::size_t at = 0; at + 2 < every_sum.size(); at += 3)
      each.push_back({static_cast<std::uint64_t>(every_sum[at]),
                      static_cast<std::uint64_t>(every_sum[at + 1]),
                      static_cast<std::uint32_t>(every_sum[at + 2])});
    header = checkpoint_pieces::encode_header(*meta, n_, payload,
                                              checkpoint_pieces::combine(each, payload));
  });

  const std::uint64_t head = checkpoint_format::kHeaderSize;
  SharedFile out(comm_, path, head + payload);
  if (rank_ == 0) out.write_at(0, header);
  for (const auto& [offset, bytes] : pieces) out.write_at(head + offset, bytes);
  out.commit();
  if (rank_ == 0) {
    ++checkpoints_;
    checkpoint_bytes_ += static_cast<double>(head + payload);
    checkpoint_seconds_ +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
}

template void MpiSolver<float>::save_checkpoint(const std::filesystem::path&, const CheckpointMeta&,
                                                Checkpoint&) const;
template void MpiSolver<double>::save_checkpoint(const std::filesystem::path&,
                                                 const CheckpointMeta&, Checkpoint&) const;
template void MpiSolver<float>::write_checkpoint_part(const std::filesystem::path*,
                                                      const CheckpointMeta*) const;
template void MpiSolver<double>::write_checkpoint_part(const std::filesystem::path*,
                                                       const CheckpointMeta*) const;

}  // namespace tridem::mpi
