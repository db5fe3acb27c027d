// encode_checkpoint / decode_checkpoint: the layout of format.hpp, and every check a
// file must pass before its numbers are trusted.
#include "io/checkpoint/byte_codec.hpp"
#include "io/checkpoint/checkpoint_pieces.hpp"
#include "io/checkpoint/crc32.hpp"
#include "io/checkpoint/format.hpp"
#include "tridem/checkpoint.hpp"

#include <algorithm>
#include <array>
#include <cstring>

namespace tridem {

namespace fmt_ = checkpoint_format;

namespace {

void get(io::ByteReader& r, double& v, const char* what) { v = r.f64(what); }
void get(io::ByteReader& r, std::int32_t& v, const char* what) { v = r.i32(what); }

std::uint32_t header_crc(std::span<const std::uint8_t> bytes) {
  return io::crc32(bytes.first(fmt_::kHeaderCrcOffset));
}

struct Header {
  std::uint32_t version = 0, precision = 0;
  std::uint64_t particles = 0, scene_hash = 0, payload_size = 0;
  std::uint32_t payload_crc = 0, header_crc = 0;
};

Header read_header(std::span<const std::uint8_t> bytes, const std::string& source) {
  if (bytes.size() < fmt_::kHeaderSize)
    throw RunError(fmt::format("{}: truncated: {} bytes, less than the {}-byte header of a "
                               "tridem checkpoint",
                               source, bytes.size(), fmt_::kHeaderSize));
  if (std::memcmp(bytes.data(), fmt_::kMagic, sizeof fmt_::kMagic) != 0)
    throw RunError(fmt::format("{}: not a tridem checkpoint (no TRIDEMCK magic number)", source));
  io::ByteReader r(bytes.subspan(sizeof fmt_::kMagic), source);
  Header h;
  h.version = r.u32("version");
  h.precision = r.u32("precision");
  h.particles = r.u64("particle count");
  h.scene_hash = r.u64("scene fingerprint");
  h.payload_size = r.u64("payload size");
  h.payload_crc = r.u32("payload checksum");
  h.header_crc = r.u32("header checksum");
  if (h.header_crc != header_crc(bytes))
    throw RunError(fmt::format("{}: corrupt: the header's checksum does not match", source));
  if (h.version < fmt_::kOldestReadVersion || h.version > fmt_::kVersion)
    throw RunError(fmt::format("{}: checkpoint format version {}; this tridem reads versions "
                               "{} to {}",
                               source, h.version, fmt_::kOldestReadVersion, fmt_::kVersion));
  if (h.precision > 1)
    throw RunError(fmt::format("{}: corrupt: unknown precision code {}", source, h.precision));
  return h;
}

/// The payload's size, checked against the file and against n before anything is sized
/// from either, so that a damaged count cannot ask for a huge allocation.
void check_sizes(const Header& h, std::size_t file_size, const std::string& source) {
  const std::uint64_t actual = file_size - fmt_::kHeaderSize;
  if (h.payload_size > actual)
    throw RunError(fmt::format("{}: truncated: {} bytes of state, the header announces {} "
                               "(the file was cut short; use an earlier checkpoint)",
                               source, actual, h.payload_size));
  if (h.payload_size < actual)
    throw RunError(fmt::format("{}: corrupt: {} bytes after the announced end of the state",
                               source, actual - h.payload_size));
  if (h.particles > (h.payload_size / fmt_::kBytesPerParticle) ||
      fmt_::fixed_payload_size(h.particles, h.version) > h.payload_size)
    throw RunError(fmt::format("{}: corrupt: {} particles do not fit in {} bytes of state",
                               source, h.particles, h.payload_size));
}

std::vector<PhysicsSetting> read_settings(io::ByteReader& r) {
  std::vector<PhysicsSetting> settings;
  const std::uint32_t k = r.u32("settings count");
  for (std::uint32_t i = 0; i < k; ++i) {
    // Each setting takes at least its two lengths: a lying count runs out of bytes first.
    std::string key = r.text("setting name");
    std::string value = r.text("setting value");
    settings.push_back({std::move(key), std::move(value)});
  }
  return settings;
}

/// The bodies' block (version 5): their count, then each body field for all bodies.
void read_bodies(io::ByteReader& r, SolverState& s, const std::string& source) {
  const std::uint64_t b = r.u64("body count");
  if (b > r.remaining() / fmt_::kBytesPerBody || b * fmt_::kBytesPerBody + 8 > r.remaining())
    throw RunError(fmt::format("{}: corrupt: {} bodies do not fit in the {} bytes of state "
                               "left after the particles",
                               source, b, r.remaining()));
  SolverState::for_each_body_column([&](auto field) {
    std::vector<double>& v = s.column(field);
    const std::string what = std::string("body ") + decltype(field)::name;
    v.resize(b);
    for (double& value : v) get(r, value, what.c_str());
  });
}

/// The bonds' block (version 6): their count, each bond's points' damage, their energies.
void read_bonds(io::ByteReader& r, SolverState& s, const std::string& source) {
  const std::uint64_t c = r.u64("bond count");
  if (c > r.remaining() / fmt_::kBytesPerBond || c * fmt_::kBytesPerBond + 8 > r.remaining())
    throw RunError(fmt::format("{}: corrupt: {} bonds do not fit in the {} bytes of state left "
                               "after the bodies",
                               source, c, r.remaining()));
  s.bond_damage.resize(c * SolverState::kBondStatePoints);
  for (double& v : s.bond_damage) get(r, v, "bond damage");
  s.bond_dissipated.resize(c);
  for (double& v : s.bond_dissipated) get(r, v, "bond energy");
}

/// An order's block (version 7): its count, then its entries.
void read_order(io::ByteReader& r, std::vector<std::int32_t>& order, const char* what,
                const std::string& source) {
  const std::uint64_t count = r.u64(what);
  if (count > r.remaining() / 4)
    throw RunError(fmt::format("{}: corrupt: a {} of {} entries does not fit in the {} bytes "
                               "of state left",
                               source, what, count, r.remaining()));
  order.resize(count);
  for (std::int32_t& id : order) id = r.i32(what);
}

SolverState read_payload(io::ByteReader& r, std::size_t n, std::uint32_t version,
                         const std::string& source, std::vector<PhysicsSetting>& settings) {
  SolverState s;
  s.step = r.i64("step");
  s.time = r.f64("time");
  settings = read_settings(r);
  if (r.remaining() < fmt_::kBytesPerParticle * n + 8)
    throw RunError(fmt::format("{}: corrupt: {} particles do not fit in the {} bytes of state "
                               "left after the settings",
                               source, n, r.remaining()));
  // The per-particle arrays, in SolverState's order (particle_fields.hpp).
  SolverState::for_each_field([&](auto field) {
    for_each_array(s.column(field), [&](std::vector<double>& v, int k) {
      const std::string what = decltype(field)::label(k);
      v.resize(n);
      for (double& value : v) get(r, value, what.c_str());
    });
  });
  if (version >= fmt_::kBodiesVersion) read_bodies(r, s, source);  // version 4: no bodies
  if (version >= fmt_::kBondsVersion) read_bonds(r, s, source);    // version 5: no bonds
  if (version >= fmt_::kOrderVersion) {                            // version 6: no order
    read_order(r, s.particle_order, "particle order", source);
    read_order(r, s.body_order, "bodies' order", source);
  }
  const std::uint64_t m = r.u64("pair count");
  if (m > r.remaining() / fmt_::kBytesPerPair || m * fmt_::kBytesPerPair != r.remaining())
    throw RunError(fmt::format("{}: corrupt: {} pairs of contact history do not fill the "
                               "{} bytes left",
                               source, m, r.remaining()));
  // Then each history field for all pairs, a field of several values pair-major.
  for_each_pair_history_field([&](auto field) {
    auto& column = s.column(field);
    column.resize(m);
    for (auto& value : column) {
      if constexpr (decltype(field)::count == 1) get(r, value, decltype(field)::name);
      else for (auto& v : value) get(r, v, decltype(field)::name);
    }
  });
  return s;
}

}  // namespace

std::vector<std::uint8_t> encode_checkpoint(const Checkpoint& c) {
  // One writer holding one slice of everything (checkpoint_pieces.hpp).
  const SolverState& s = c.state;
  const std::vector<std::uint8_t> opening =
      checkpoint_pieces::encode_opening(c.meta, s.step, s.time);
  const checkpoint_pieces::Counts total{
      s.size(), s.bodies(), s.bonds(), s.pairs(), s.particle_order.size(), s.body_order.size()};
  const std::uint64_t size = checkpoint_pieces::payload_size(opening.size(), total);
  std::vector<std::uint8_t> bytes(fmt_::kHeaderSize + size);
  const std::span<std::uint8_t> payload = std::span(bytes).subspan(fmt_::kHeaderSize);
  std::copy(opening.begin(), opening.end(), payload.begin());
  checkpoint_pieces::encode_slice(s, {}, total, opening.size(), true,
                                  [&](std::uint64_t offset, std::span<const std::uint8_t> piece) {
                                    std::copy(piece.begin(), piece.end(),
                                              payload.begin() +
                                                  static_cast<std::ptrdiff_t>(offset));
                                  });
  const std::vector<std::uint8_t> header =
      checkpoint_pieces::encode_header(c.meta, s.size(), size, io::crc32(payload));
  std::copy(header.begin(), header.end(), bytes.begin());
  return bytes;
}

Checkpoint decode_checkpoint(std::span<const std::uint8_t> bytes, const std::string& source) {
  const Header h = read_header(bytes, source);
  check_sizes(h, bytes.size(), source);
  const auto payload = bytes.subspan(fmt_::kHeaderSize);
  if (io::crc32(payload) != h.payload_crc)
    throw RunError(fmt::format("{}: corrupt: the state's checksum does not match (the file "
                               "was damaged; use an earlier checkpoint)",
                               source));
  io::ByteReader r(payload, source);
  Checkpoint c;
  c.meta.precision = h.precision == 1 ? Precision::Float : Precision::Double;
  c.meta.scene_hash = h.scene_hash;
  c.state =
      read_payload(r, static_cast<std::size_t>(h.particles), h.version, source, c.meta.settings);
  validate_solver_state(c.state, c.state.size(), c.state.bodies(), source);
  validate_bond_state(c.state, c.state.bonds(), source);
  return c;
}

}  // namespace tridem
