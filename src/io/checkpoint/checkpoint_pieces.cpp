// The layout of format.hpp as offsets, so that a slice of the state is written where the
// whole file has it.
#include "io/checkpoint/checkpoint_pieces.hpp"

#include "io/checkpoint/byte_codec.hpp"
#include "io/checkpoint/crc32.hpp"
#include "io/checkpoint/format.hpp"
#include "tridem/error.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <utility>

namespace tridem::checkpoint_pieces {

namespace layout = checkpoint_format;

namespace {

void put(io::ByteWriter& w, double v) { w.f64(v); }
void put(io::ByteWriter& w, std::int32_t v) { w.i32(v); }

[[noreturn]] void misfit(const char* what, std::size_t got, std::uint64_t first,
                         std::uint64_t total) {
  throw RunError(fmt::format("internal error: a checkpoint slice of {} {} from {} does not "
                             "fit in the file's {}",
                             got, what, first, total));
}

/// Bytes of one pair's value of a history field.
template <class Field>
constexpr std::uint64_t pair_bytes() {
  return Field::count * sizeof(typename Field::type);
}

}  // namespace

std::vector<std::uint8_t> encode_opening(const CheckpointMeta& meta, std::int64_t step,
                                         double time) {
  std::vector<std::uint8_t> bytes;
  io::ByteWriter w(bytes);
  w.i64(step);
  w.f64(time);
  w.u32(static_cast<std::uint32_t>(meta.settings.size()));
  for (const PhysicsSetting& setting : meta.settings) {
    w.text(setting.key);
    w.text(setting.value);
  }
  return bytes;
}

std::uint64_t payload_size(std::uint64_t opening_size, const Counts& total) {
  return opening_size + layout::kBytesPerParticle * total.particles + 8 +
         layout::kBytesPerBody * total.bodies + 8 + layout::kBytesPerBond * total.bonds + 8 +
         4 * total.ordered + 8 + 4 * total.ordered_bodies + 8 + layout::kBytesPerPair * total.pairs;
}

void encode_slice(const SolverState& s, const Counts& first, const Counts& total,
                  std::uint64_t opening_size, bool counts, const Emit& emit) {
  const std::size_t n = s.size();
  if (first.particles + n > total.particles)
    misfit("particles", n, first.particles, total.particles);
  if (first.bodies + s.bodies() > total.bodies)
    misfit("bodies", s.bodies(), first.bodies, total.bodies);
  if (first.bonds + s.bonds() > total.bonds) misfit("bonds", s.bonds(), first.bonds, total.bonds);
  if (first.pairs + s.pairs() > total.pairs) misfit("pairs", s.pairs(), first.pairs, total.pairs);
  // The order is written whole by the writer that counts, or not at all.
  const bool order = counts && total.ordered + total.ordered_bodies > 0;
  if (order && (total.ordered != total.particles || total.ordered_bodies != total.bodies))
    misfit("entries of an order", total.ordered, total.ordered_bodies, total.particles);
  if (!s.particle_order.empty() || !s.body_order.empty()) {
    if (!order || s.particle_order.size() != total.ordered)
      misfit("entries of the particle order", s.particle_order.size(), 0, total.ordered);
    if (s.body_order.size() != total.ordered_bodies)
      misfit("entries of the bodies' order", s.body_order.size(), 0, total.ordered_bodies);
  } else if (order) {
    misfit("entries of the particle order", 0, 0, total.ordered);
  }
  // Every array of a block as long as the block: else its pieces would not tile the file.
  SolverState::for_each_body_column([&](auto field) {
    if (s.column(field).size() != s.bodies())
      misfit("values of a body array", s.column(field).size(), first.bodies, s.bodies());
  });
  if (s.bond_damage.size() != SolverState::kBondStatePoints * s.bonds())
    misfit("bond damage values", s.bond_damage.size(), first.bonds, s.bonds());
  for_each_pair_history_field([&](auto field) {
    if (s.column(field).size() != s.pairs())
      misfit("values of a pair array", s.column(field).size(), first.pairs, s.pairs());
  });
  std::vector<std::uint8_t> bytes;
  io::ByteWriter w(bytes);
  // Emits what `w` wrote at `offset`, and starts the next piece.
  auto flush = [&](std::uint64_t offset) {
    if (!bytes.empty()) emit(offset, bytes);
    bytes.clear();
  };
  std::uint64_t at = opening_size;  // where the current array starts
  SolverState::for_each_field([&](auto field) {
    for_each_array(s.column(field), [&](const std::vector<double>& v, int) {
      if (v.empty() && decltype(field)::role == FieldRole::Sum) {  // empty: zeros
        for (std::size_t i = 0; i < n; ++i) put(w, 0.0);
      } else {
        if (v.size() != n) misfit("values of an array", v.size(), first.particles, n);
        for (double value : v) put(w, value);
      }
      flush(at + 8 * first.particles);
      at += 8 * total.particles;
    });
  });
  if (counts) w.u64(total.bodies);
  flush(at);
  at += 8;
  SolverState::for_each_body_column([&](auto field) {
    for (double value : s.column(field)) put(w, value);
    flush(at + 8 * first.bodies);
    at += 8 * total.bodies;
  });
  if (counts) w.u64(total.bonds);
  flush(at);
  at += 8;
  constexpr std::uint64_t kPoints = SolverState::kBondStatePoints;
  for (double value : s.bond_damage) put(w, value);
  flush(at + 8 * kPoints * first.bonds);
  at += 8 * kPoints * total.bonds;
  for (double value : s.bond_dissipated) put(w, value);
  flush(at + 8 * first.bonds);
  at += 8 * total.bonds;
  for (const auto& [entries, count] : {std::pair{&s.particle_order, total.ordered},
                                       std::pair{&s.body_order, total.ordered_bodies}}) {
    if (counts) w.u64(count);
    for (const std::int32_t id : *entries) put(w, id);
    flush(at);
    at += 8 + 4 * count;
  }
  if (counts) w.u64(total.pairs);
  flush(at);
  at += 8;
  for_each_pair_history_field([&](auto field) {
    using Field = decltype(field);
    for (const auto& value : s.column(field)) {
      if constexpr (Field::count == 1)
        put(w, value);
      else
        for (auto v : value) put(w, v);
    }
    flush(at + pair_bytes<Field>() * first.pairs);
    at += pair_bytes<Field>() * total.pairs;
  });
}

std::vector<std::uint8_t> encode_header(const CheckpointMeta& meta, std::uint64_t particles,
                                        std::uint64_t payload_size, std::uint32_t payload_crc) {
  std::vector<std::uint8_t> bytes;
  bytes.reserve(layout::kHeaderSize);
  io::ByteWriter h(bytes);
  for (char ch : layout::kMagic) bytes.push_back(static_cast<std::uint8_t>(ch));
  h.u32(layout::kVersion);
  h.u32(meta.precision == Precision::Float ? 1 : 0);
  h.u64(particles);
  h.u64(meta.scene_hash);
  h.u64(payload_size);
  h.u32(payload_crc);
  h.u32(io::crc32(bytes));  // of bytes 0..43: the header's own checksum
  return bytes;
}

std::uint32_t combine(std::vector<PieceSum> pieces, std::uint64_t payload_size) {
  std::erase_if(pieces, [](const PieceSum& p) { return p.size == 0; });
  std::sort(pieces.begin(), pieces.end(),
            [](const PieceSum& a, const PieceSum& b) { return a.offset < b.offset; });
  std::uint32_t crc = io::crc32({});
  std::uint64_t end = 0;
  for (const PieceSum& p : pieces) {
    if (p.offset != end)
      throw RunError(fmt::format("internal error: checkpoint pieces {} at byte {} (the last "
                                 "ended at {})",
                                 p.offset < end ? "overlap" : "leave a gap", p.offset, end));
    crc = io::crc32_combine(crc, p.crc, p.size);
    end = p.offset + p.size;
  }
  if (end != payload_size)
    throw RunError(
        fmt::format("internal error: checkpoint pieces end at byte {} of {}", end, payload_size));
  return crc;
}

}  // namespace tridem::checkpoint_pieces
