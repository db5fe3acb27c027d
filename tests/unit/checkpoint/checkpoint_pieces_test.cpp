// A checkpoint written in pieces (io/checkpoint/checkpoint_pieces.hpp, as the MPI ranks
// write it side by side): any split of the state into slices gives, piece by piece and
// checksum by checksum, the bytes of the one-writer file.
#include "io/checkpoint/checkpoint_pieces.hpp"
#include "io/checkpoint/crc32.hpp"
#include "io/checkpoint/format.hpp"
#include "tridem/checkpoint.hpp"
#include "tridem/error.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <string_view>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

namespace pieces = checkpoint_pieces;

std::span<const std::uint8_t> bytes_of(std::string_view text) {
  return {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()};
}

TEST(Crc32, KnownValueAndCombinedPieces) {
  const std::string_view text = "123456789";
  EXPECT_EQ(io::crc32(bytes_of(text)), 0xCBF43926u);  // the CRC-32 check value
  EXPECT_EQ(io::crc32({}), 0u);
  for (std::size_t cut = 0; cut <= text.size(); ++cut) {
    const auto a = bytes_of(text.substr(0, cut)), b = bytes_of(text.substr(cut));
    EXPECT_EQ(io::crc32_combine(io::crc32(a), io::crc32(b), b.size()), 0xCBF43926u) << cut;
  }
}

/// 7 particles, 3 bodies, 4 bonds, 6 pairs; the local damping's sums left empty (zeros).
Checkpoint sample() {
  Checkpoint c;
  c.meta = {Precision::Double,
            0xFEDCBA9876543210ull,
            {{"[simulation] dt", "2e-06"}, {"[material.rock] friction", "0.5"}}};
  SolverState& s = c.state;
  s.step = 77;
  s.time = 1.5e-4;
  for (int i = 0; i < 7; ++i) {
    const double v = 0.125 * i - 0.3;
    s.x.push_back(v);
    s.y.push_back(-v / 3);
    s.theta.push_back(v * v);
    s.vx.push_back(1 + v);
    s.vy.push_back(2 - v);
    s.omega.push_back(1e-3 * i);
    s.energy[kDissipatedDamping].push_back(0.5 * i);
    s.energy[kDissipatedFriction].push_back(1.0 / (i + 1));
    s.energy[kWallWork].push_back(-0.25 * i);
  }
  s.pair_emitter = {0, 0, 2, 3, 3, 6};
  s.pair_partner = {1, 4, 5, 4, 6, 5};
  s.pair_slip = {{1e-9, 0}, {-2e-9, 3e-9}, {0, 1}, {4, -4}, {1.0 / 3, 0}, {-0.0, 7}};
  s.body_x = {0.5, -1, 2};
  s.body_y = {0, 1, 1e-300};
  s.body_theta = {0.1, 0.2, 0.3};
  s.body_vx = {1, 2, 3};
  s.body_vy = {-1, -2, -3};
  s.body_omega = {9, 8, 7};
  s.bond_damage = {0, 0.25, 1, 1, 0.5, 0, 0.75, 0.125};
  s.bond_dissipated = {0, 1e-6, 2e-6, 0};
  return c;
}

std::vector<double> range(const std::vector<double>& v, std::size_t from, std::size_t to) {
  return {v.begin() + static_cast<std::ptrdiff_t>(from),
          v.begin() + static_cast<std::ptrdiff_t>(to)};
}

std::size_t first_of(std::size_t total, std::size_t k, std::size_t slices) {
  return total * k / slices;
}

/// Slice k of `slices` of the whole state: particles, bodies and bonds by index, pairs by
/// their emitter's slice.
SolverState slice(const SolverState& s, std::size_t k, std::size_t slices, pieces::Counts& first) {
  SolverState part;
  part.step = s.step;
  part.time = s.time;
  const std::size_t p0 = first_of(s.size(), k, slices), p1 = first_of(s.size(), k + 1, slices);
  const std::size_t b0 = first_of(s.bodies(), k, slices), b1 = first_of(s.bodies(), k + 1, slices);
  const std::size_t c0 = first_of(s.bonds(), k, slices), c1 = first_of(s.bonds(), k + 1, slices);
  SolverState::for_each_field([&](auto field) {
    std::vector<const std::vector<double>*> from;
    for_each_array(s.column(field), [&](const std::vector<double>& v, int) { from.push_back(&v); });
    for_each_array(part.column(field), [&](std::vector<double>& to, int a) {
      const std::vector<double>& v = *from[static_cast<std::size_t>(a)];
      if (!v.empty()) to = range(v, p0, p1);  // an empty array of sums stays empty: zeros
    });
  });
  SolverState::for_each_body_column(
      [&](auto field) { part.column(field) = range(s.column(field), b0, b1); });
  constexpr std::size_t kPoints = SolverState::kBondStatePoints;
  part.bond_damage = range(s.bond_damage, kPoints * c0, kPoints * c1);
  part.bond_dissipated = range(s.bond_dissipated, c0, c1);
  first = {p0, b0, c0, 0};
  for (std::size_t p = 0; p < s.pairs(); ++p) {
    const auto e = static_cast<std::size_t>(s.pair_emitter[p]);
    if (e < p0) ++first.pairs;
    if (e < p0 || e >= p1) continue;
    part.pair_emitter.push_back(s.pair_emitter[p]);
    part.pair_partner.push_back(s.pair_partner[p]);
    part.pair_slip.push_back(s.pair_slip[p]);
  }
  return part;
}

TEST(CheckpointPieces, SlicesWrittenApartGiveTheOneWriterFile) {
  const Checkpoint c = sample();
  const std::vector<std::uint8_t> one = encode_checkpoint(c);
  const pieces::Counts total{c.state.size(), c.state.bodies(), c.state.bonds(), c.state.pairs()};
  const std::vector<std::uint8_t> opening =
      pieces::encode_opening(c.meta, c.state.step, c.state.time);
  const std::uint64_t payload = pieces::payload_size(opening.size(), total);
  ASSERT_EQ(one.size(), checkpoint_format::kHeaderSize + payload);
  // 8 slices: some hold no body, no bond or no pair.
  for (std::size_t slices : {1, 2, 3, 5, 8}) {
    std::vector<std::uint8_t> file(one.size(), 0xAB);
    std::vector<pieces::PieceSum> sums;
    auto put = [&](std::uint64_t offset, std::span<const std::uint8_t> bytes) {
      std::memcpy(file.data() + checkpoint_format::kHeaderSize + offset, bytes.data(),
                  bytes.size());
      sums.push_back({offset, bytes.size(), io::crc32(bytes)});
    };
    put(0, opening);
    for (std::size_t k = 0; k < slices; ++k) {
      pieces::Counts first;
      const SolverState part = slice(c.state, k, slices, first);
      pieces::encode_slice(part, first, total, opening.size(), k == 0, put);
    }
    const auto header =
        pieces::encode_header(c.meta, total.particles, payload, pieces::combine(sums, payload));
    std::memcpy(file.data(), header.data(), header.size());
    EXPECT_EQ(file, one) << slices << " slices";
    EXPECT_EQ(decode_checkpoint(file, "pieces").state.pair_slip, c.state.pair_slip);
  }
}

TEST(CheckpointPieces, CombineRefusesGapsAndOverlaps) {
  const std::string_view text = "0123456789";
  auto sum = [&](std::uint64_t at, std::uint64_t size) {
    return pieces::PieceSum{at, size, io::crc32(bytes_of(text.substr(at, size)))};
  };
  EXPECT_EQ(pieces::combine({sum(4, 6), sum(0, 4), sum(4, 0)}, 10), io::crc32(bytes_of(text)));
  EXPECT_THROW(pieces::combine({sum(0, 4), sum(5, 5)}, 10), RunError);  // a gap
  EXPECT_THROW(pieces::combine({sum(0, 5), sum(4, 6)}, 10), RunError);  // an overlap
  EXPECT_THROW(pieces::combine({sum(0, 4)}, 10), RunError);             // short of the end
}

TEST(CheckpointPieces, ASliceThatDoesNotFitIsAnInternalError) {
  const Checkpoint c = sample();
  const pieces::Counts total{c.state.size(), c.state.bodies(), c.state.bonds(), c.state.pairs()};
  const pieces::Counts late{3, 0, 0, 0};  // 7 particles from the fourth: past the end
  EXPECT_THROW(pieces::encode_slice(c.state, late, total, 0, false,
                                    [](std::uint64_t, std::span<const std::uint8_t>) {}),
               RunError);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
