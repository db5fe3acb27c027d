// Checkpoint files: exact round trip, and refusal with a message (never a crash, never a
// wrong state) of every truncation, flipped bits, another format, scene or precision.
#include "io/checkpoint/crc32.hpp"
#include "io/checkpoint/format.hpp"
#include "support/scene_builder.hpp"
#include "tridem/checkpoint.hpp"
#include "tridem/error.hpp"
#include "unit/io/io_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numeric>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

Checkpoint sample_checkpoint() {
  Checkpoint c;
  c.meta = {Precision::Float, 0x0123456789ABCDEFull,
            {{"[simulation] method", "single-domain"}, {"[simulation] dt", "1e-05"}, {"", ""}}};
  SolverState& s = c.state;
  s.step = 1234;
  s.time = 0.1 + 0.2;
  s.x = {1.0 / 3, -2.5, 1e-300};
  s.y = {0, -0.0, 7};
  s.theta = {3.14159, 0, -1};
  s.vx = {1, 2, 3};
  s.vy = {-1, -2, -3};
  s.omega = {0.5, std::numeric_limits<double>::denorm_min(), 0};
  s.pair_emitter = {0, 0, 1};
  s.pair_partner = {1, 2, 2};
  s.pair_slip = {{1e-9, -0.0}, {0, 1}, {-3e-8, 0}};
  s.energy[kDissipatedDamping] = {0.25, 1e-300, 3};
  s.energy[kDissipatedFriction] = {-0.0, 0, 7.5};
  s.energy[kWallWork] = {-2, 0, 1.0 / 3};  // local damping left empty: zeros
  // Two bodies (of particles 0-1 and 2, say): their block of version 5.
  s.body_x = {0.5, -0.0};
  s.body_y = {1e-300, 2};
  s.body_theta = {-3, 0.25};
  s.body_vx = {1.0 / 7, 0};
  s.body_vy = {-9.5, std::numeric_limits<double>::denorm_min()};
  s.body_omega = {12, -1};
  return c;
}

/// `c` (without bonds or an order) as `version` wrote it: 6, the same layout without the
/// orders' counts; 5, without the bonds' count too; 4 (`c` without bodies too), without the
/// bodies' count either.
std::vector<std::uint8_t> older_bytes(const Checkpoint& c, std::uint32_t version) {
  namespace layout = checkpoint_format;
  EXPECT_EQ(c.state.bonds(), 0u);
  EXPECT_TRUE(c.state.particle_order.empty());
  auto bytes = encode_checkpoint(c);
  std::size_t settings = 4;
  for (const PhysicsSetting& p : c.meta.settings) settings += 8 + p.key.size() + p.value.size();
  const std::size_t body_count_at =
      layout::kHeaderSize + 16 + settings + layout::kBytesPerParticle * c.state.size();
  const std::size_t bond_count_at = body_count_at + 8 + layout::kBytesPerBody * c.state.bodies();
  const std::size_t order_counts_at = bond_count_at + 8;
  bytes.erase(bytes.begin() + static_cast<std::ptrdiff_t>(order_counts_at),
              bytes.begin() + static_cast<std::ptrdiff_t>(order_counts_at + 16));
  if (version <= 5)
    bytes.erase(bytes.begin() + static_cast<std::ptrdiff_t>(bond_count_at),
                bytes.begin() + static_cast<std::ptrdiff_t>(bond_count_at + 8));
  if (version == 4)
    bytes.erase(bytes.begin() + static_cast<std::ptrdiff_t>(body_count_at),
                bytes.begin() + static_cast<std::ptrdiff_t>(body_count_at + 8));
  auto put_u32 = [&](std::size_t at, std::uint32_t v) {
    for (int k = 0; k < 4; ++k) bytes[at + k] = static_cast<std::uint8_t>(v >> (8 * k));
  };
  const std::uint64_t payload = bytes.size() - layout::kHeaderSize;
  for (int k = 0; k < 8; ++k) bytes[32 + k] = static_cast<std::uint8_t>(payload >> (8 * k));
  put_u32(8, version);
  put_u32(layout::kPayloadCrcOffset, io::crc32(std::span(bytes).subspan(layout::kHeaderSize)));
  put_u32(layout::kHeaderCrcOffset, io::crc32(std::span(bytes).first(layout::kHeaderCrcOffset)));
  return bytes;
}

void expect_refused(std::span<const std::uint8_t> bytes, const std::string& fragment) {
  try {
    decode_checkpoint(bytes, "ck.bin");
    ADD_FAILURE() << "accepted; expected '" << fragment << "'";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("ck.bin"), std::string::npos) << message;
    EXPECT_NE(message.find(fragment), std::string::npos) << message;
  }
}

TEST(CheckpointFile, RoundTripIsExact) {
  const Checkpoint c = sample_checkpoint();
  const Checkpoint back = decode_checkpoint(encode_checkpoint(c), "mem");
  EXPECT_EQ(back.meta.precision, Precision::Float);
  EXPECT_EQ(back.meta.scene_hash, c.meta.scene_hash);
  EXPECT_EQ(back.meta.settings, c.meta.settings);
  EXPECT_EQ(back.state.step, c.state.step);
  EXPECT_EQ(back.state.time, c.state.time);
  EXPECT_EQ(back.state.x, c.state.x);
  EXPECT_TRUE(std::signbit(back.state.y[1]));
  EXPECT_EQ(back.state.omega, c.state.omega);
  EXPECT_EQ(back.state.pair_emitter, c.state.pair_emitter);
  EXPECT_EQ(back.state.pair_partner, c.state.pair_partner);
  EXPECT_EQ(back.state.pair_slip, c.state.pair_slip);
  EXPECT_TRUE(std::signbit(back.state.pair_slip[0][1]));
  EXPECT_EQ(back.state.energy[kDissipatedDamping], c.state.energy[kDissipatedDamping]);
  EXPECT_EQ(back.state.energy[kDissipatedFriction], c.state.energy[kDissipatedFriction]);
  EXPECT_TRUE(std::signbit(back.state.energy[kDissipatedFriction][0]));
  EXPECT_EQ(back.state.energy[kDissipatedLocal], (std::vector<double>{0, 0, 0}));
  EXPECT_EQ(back.state.energy[kWallWork], c.state.energy[kWallWork]);
  SolverState::for_each_body_column([&](auto field) {
    EXPECT_EQ(back.state.column(field), c.state.column(field)) << decltype(field)::name;
  });
  EXPECT_TRUE(std::signbit(back.state.body_x[1]));
}

TEST(CheckpointFile, BodilessStateHasNoBodies) {
  Checkpoint c = sample_checkpoint();
  SolverState::for_each_body_column([&](auto field) { c.state.column(field).clear(); });
  const Checkpoint back = decode_checkpoint(encode_checkpoint(c), "mem");
  EXPECT_EQ(back.state.bodies(), 0u);
  EXPECT_TRUE(back.state.body_omega.empty());
  EXPECT_EQ(back.state.x, c.state.x);
}

// Version 4 (before bodies) is still read: the same state, with no bodies.
TEST(CheckpointFile, Version4IsReadAsAStateWithoutBodies) {
  Checkpoint c = sample_checkpoint();
  SolverState::for_each_body_column([&](auto field) { c.state.column(field).clear(); });
  const auto v4 = older_bytes(c, 4);
  EXPECT_EQ(v4.size() + 32, encode_checkpoint(c).size());
  const Checkpoint back = decode_checkpoint(v4, "old.ckpt");
  EXPECT_EQ(back.state.bodies(), 0u);
  EXPECT_EQ(back.state.step, c.state.step);
  EXPECT_EQ(back.state.x, c.state.x);
  EXPECT_EQ(back.state.omega, c.state.omega);
  EXPECT_EQ(back.state.energy[kWallWork], c.state.energy[kWallWork]);
  EXPECT_EQ(back.state.pair_partner, c.state.pair_partner);
  EXPECT_EQ(back.state.pair_slip, c.state.pair_slip);
  EXPECT_EQ(back.meta.settings, c.meta.settings);
  for (std::size_t size = 0; size < v4.size(); ++size)
    expect_refused(std::span(v4).first(size), "truncated");
}

TEST(CheckpointFile, Version5IsReadAsAStateWithoutBonds) {
  const Checkpoint c = sample_checkpoint();
  const auto v5 = older_bytes(c, 5);
  EXPECT_EQ(v5.size() + 24, encode_checkpoint(c).size());
  const Checkpoint back = decode_checkpoint(v5, "old.ckpt");
  EXPECT_EQ(back.state.bonds(), 0u);
  EXPECT_TRUE(back.state.bond_damage.empty());
  EXPECT_EQ(back.state.body_omega, c.state.body_omega);
  EXPECT_EQ(back.state.pair_slip, c.state.pair_slip);
  for (std::size_t size = 0; size < v5.size(); ++size)
    expect_refused(std::span(v5).first(size), "truncated");
}

TEST(CheckpointFile, Version6IsReadAsAStateInTheOrderTheSceneGives) {
  const Checkpoint c = sample_checkpoint();
  const auto v6 = older_bytes(c, 6);
  EXPECT_EQ(v6.size() + 16, encode_checkpoint(c).size());
  const Checkpoint back = decode_checkpoint(v6, "old.ckpt");
  EXPECT_TRUE(back.state.particle_order.empty());
  EXPECT_EQ(back.state.x, c.state.x);
  EXPECT_EQ(back.state.pair_slip, c.state.pair_slip);
  for (std::size_t size = 0; size < v6.size(); ++size)
    expect_refused(std::span(v6).first(size), "truncated");
}

// A run renumbered mid-way (core/place_numbered_solver) keeps its particles' order.
TEST(CheckpointFile, TheParticleOrderRoundTripsAndABadOneIsRefused) {
  Checkpoint c = sample_checkpoint();
  c.state.particle_order.resize(c.state.size());
  std::iota(c.state.particle_order.rbegin(), c.state.particle_order.rend(), 0);
  c.state.body_order.resize(c.state.bodies());
  std::iota(c.state.body_order.rbegin(), c.state.body_order.rend(), 0);
  const auto bytes = encode_checkpoint(c);
  EXPECT_EQ(bytes.size(), encode_checkpoint(sample_checkpoint()).size() +
                              4 * (c.state.size() + c.state.bodies()));
  const Checkpoint back = decode_checkpoint(bytes, "mem");
  EXPECT_EQ(back.state.particle_order, c.state.particle_order);
  EXPECT_EQ(back.state.body_order, c.state.body_order);
  EXPECT_EQ(back.state.pair_slip, c.state.pair_slip);
  for (std::size_t size = 0; size < bytes.size(); ++size)
    expect_refused(std::span(bytes).first(size), "truncated");
  c.state.particle_order.pop_back();  // an order names every particle: never written
  EXPECT_THROW(encode_checkpoint(c), RunError);
}

TEST(CheckpointFile, BondsRoundTripAndBadOnesAreRefused) {
  Checkpoint c = sample_checkpoint();
  c.state.bond_damage = {0, 0.5, 1, 1, 1.0 / 3, 0};
  c.state.bond_dissipated = {0, 0.25, 1e-300};
  const Checkpoint back = decode_checkpoint(encode_checkpoint(c), "mem");
  EXPECT_EQ(back.state.bond_damage, c.state.bond_damage);
  EXPECT_EQ(back.state.bond_dissipated, c.state.bond_dissipated);
  c.state.bond_damage[1] = 2;  // damage above 1
  expect_refused(encode_checkpoint(c), "damage");
  c.state.bond_damage.pop_back();  // two values per bond: such a state is never written
  EXPECT_THROW(encode_checkpoint(c), RunError);
}

// A body count that the bytes left cannot hold is refused before anything is sized by it.
TEST(CheckpointFile, LyingBodyCountIsRefused) {
  Checkpoint c = sample_checkpoint();
  auto bytes = encode_checkpoint(c);
  std::size_t settings = 4;
  for (const PhysicsSetting& p : c.meta.settings) settings += 8 + p.key.size() + p.value.size();
  const std::size_t at = checkpoint_format::kHeaderSize + 16 + settings +
                         checkpoint_format::kBytesPerParticle * c.state.size();
  ASSERT_EQ(bytes[at], 2);  // the two bodies
  bytes[at + 6] = 0x7f;
  auto put_u32 = [&](std::size_t pos, std::uint32_t v) {
    for (int k = 0; k < 4; ++k) bytes[pos + k] = static_cast<std::uint8_t>(v >> (8 * k));
  };
  put_u32(checkpoint_format::kPayloadCrcOffset,
          io::crc32(std::span(bytes).subspan(checkpoint_format::kHeaderSize)));
  put_u32(checkpoint_format::kHeaderCrcOffset,
          io::crc32(std::span(bytes).first(checkpoint_format::kHeaderCrcOffset)));
  expect_refused(bytes, "bodies do not fit");
}

TEST(CheckpointFile, WriteAndReadThroughDisk) {
  test::TempDir dir;
  const auto file = dir.path() / "run.ckpt";
  write_checkpoint(file, sample_checkpoint());
  EXPECT_EQ(read_checkpoint(file).state.x, sample_checkpoint().state.x);
  EXPECT_THROW(read_checkpoint(dir.path() / "missing.ckpt"), RunError);
}

TEST(CheckpointFile, EveryTruncationIsRefused) {
  const auto bytes = encode_checkpoint(sample_checkpoint());
  for (std::size_t size = 0; size < bytes.size(); ++size)
    expect_refused(std::span(bytes).first(size), "truncated");
}

TEST(CheckpointFile, FlippedBitsAreRefused) {
  const auto good = encode_checkpoint(sample_checkpoint());
  for (std::size_t byte = 0; byte < good.size(); ++byte) {
    auto bytes = good;
    bytes[byte] ^= 0x10;
    EXPECT_THROW(decode_checkpoint(bytes, "ck.bin"), Error) << "flip in byte " << byte;
  }
  auto payload = good;
  payload[payload.size() - 1] ^= 1;
  expect_refused(payload, "checksum");
}

TEST(CheckpointFile, TrailingBytesAndOtherFilesAreRefused) {
  auto bytes = encode_checkpoint(sample_checkpoint());
  bytes.push_back(0);
  expect_refused(bytes, "after the announced end");
  const std::string toml = "[simulation]\nsteps = 10\n# padding padding padding padding padding\n";
  expect_refused({reinterpret_cast<const std::uint8_t*>(toml.data()), toml.size()},
                 "not a tridem checkpoint");
}

TEST(CheckpointFile, OtherVersionIsRefusedByName) {
  // Versions 1 (before the physics settings), 2 (before the energy sums) and 3 (six edge
  // slips per pair, before the contact of issue 10), and the next one (8), with a
  // consistent header checksum: refused for the version, not as damage.
  Checkpoint c = sample_checkpoint();
  auto bytes = encode_checkpoint(c);
  for (const int version : {1, 2, 3, 8}) {
    bytes[8] = static_cast<std::uint8_t>(version);
    const std::uint32_t crc = io::crc32(std::span(bytes).first(44));  // as the writer does
    for (int k = 0; k < 4; ++k) bytes[44 + k] = static_cast<std::uint8_t>(crc >> (8 * k));
    expect_refused(bytes, "checkpoint format version " + std::to_string(version) +
                              "; this tridem reads versions 4 to 7");
  }
}

TEST(CheckpointFile, ValidFileOfAnotherSceneOrPrecisionIsRefused) {
  Scene scene = test::empty_scene();
  scene.triangles.push_back(test::triangle({0, 0}, {1, 0}, {0, 1}));
  scene.triangles.push_back(test::triangle({2, 0}, {3, 0}, {2, 1}));
  scene.triangles.push_back(test::triangle({4, 0}, {5, 0}, {4, 1}));
  const double dt = 1e-5;
  auto run_of = [&](const Scene& s, Precision p) {
    return CheckpointMeta{p, scene_fingerprint(s), physics_settings(s, dt)};
  };
  Checkpoint c = sample_checkpoint();
  c.meta = run_of(scene, Precision::Double);
  EXPECT_NO_THROW(check_checkpoint_fits(c, "ck.bin", scene, c.meta));

  auto refused = [&](const Scene& other, Precision p, const std::string& fragment) {
    try {
      check_checkpoint_fits(c, "ck.bin", other, run_of(other, p));
      ADD_FAILURE() << "accepted; expected '" << fragment << "'";
    } catch (const RunError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  refused(scene, Precision::Float, "precision = \"double\"");
  Scene moved = scene;
  moved.triangles[1].vertices[0].x += 1e-12;
  refused(moved, Precision::Double, "another scene");
  Scene denser = scene;
  denser.materials[0].density *= 2;
  refused(denser, Precision::Double, "another scene");
  Scene fewer = scene;
  fewer.triangles.pop_back();
  refused(fewer, Precision::Double, "2");
}

// A restart must not silently continue with other physics: every setting that changes the
// trajectory is stored, and a change is refused naming the key and both values.
TEST(CheckpointFile, OtherPhysicsSettingsAreRefusedNamingBothValues) {
  Scene scene = test::empty_scene();
  for (double x : {0.0, 2.0, 4.0}) scene.triangles.push_back(test::triangle({x, 0}, {x + 1, 0}, {x, 1}));
  scene.materials[0].penalty = 1e6;
  Checkpoint c = sample_checkpoint();
  c.meta = {Precision::Double, scene_fingerprint(scene), physics_settings(scene, 1e-5)};
  c.meta.settings = decode_checkpoint(encode_checkpoint(c), "mem").meta.settings;
  auto refused = [&](const Scene& other, double dt, const std::string& fragment) {
    const CheckpointMeta run{Precision::Double, scene_fingerprint(other),
                             physics_settings(other, dt)};
    try {
      check_checkpoint_fits(c, "ck.bin", other, run);
      ADD_FAILURE() << "accepted; expected '" << fragment << "'";
    } catch (const RunError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  EXPECT_NO_THROW(check_checkpoint_fits(
      c, "ck.bin", scene, {Precision::Double, scene_fingerprint(scene), physics_settings(scene, 1e-5)}));
  Scene other = scene;
  other.simulation.method = Method::SingleDomain;
  refused(other, 1e-5, "[simulation] method = grid, this run has single-domain");
  other = scene;
  other.simulation.method = Method::Decomposition;
  other.simulation.contact_test = ContactTest::DirectArea;
  refused(other, 1e-5, "method = grid");
  other = scene;
  other.simulation.bbox_prefilter = false;
  refused(other, 1e-5, "bbox_prefilter = true, this run has false");
  refused(scene, 2e-5, "dt = 1e-05, this run has 2e-05");
  other = scene;
  other.materials[0].penalty *= 10;
  refused(other, 1e-5, "penalty = 1000000, this run has 10000000");
  other = scene;
  other.simulation.gravity.y = -9.81;
  refused(other, 1e-5, "gravity = [0, 0], this run has [0, -9.81]");
  other = scene;
  other.materials[0].name = "renamed";
  refused(other, 1e-5, "does not record [[material]] \"renamed\"");
  // Settings that change no result may differ: a CPU checkpoint continues on the GPU.
  other = scene;
  other.simulation.backend = Backend::Cuda;
  other.simulation.skin = 0.2;
  other.output.every = 7;
  EXPECT_NO_THROW(check_checkpoint_fits(
      c, "ck.bin", other, {Precision::Double, scene_fingerprint(other), physics_settings(other, 1e-5)}));
}

// A periodic run resumed with another cell would wrap and image its grains elsewhere (and
// shear them at another rate): the cell is a physics setting, refused when changed, added,
// or removed, naming the key and both values.
TEST(CheckpointFile, AnotherPeriodicCellIsRefused) {
  Scene scene = test::empty_scene();
  for (double x : {0.0, 2.0, 4.0})
    scene.triangles.push_back(test::triangle({x, 0}, {x + 1, 0}, {x, 1}));
  scene.simulation.periodic.x = PeriodicRange{-1, 7};
  scene.simulation.periodic.y = PeriodicRange{-1, 7};
  scene.simulation.periodic.shear_rate = 2;
  Checkpoint c = sample_checkpoint();
  c.meta = {Precision::Double, scene_fingerprint(scene), physics_settings(scene, 1e-5)};
  c.meta.settings = decode_checkpoint(encode_checkpoint(c), "mem").meta.settings;
  auto run_of = [](const Scene& s) {
    return CheckpointMeta{Precision::Double, scene_fingerprint(s), physics_settings(s, 1e-5)};
  };
  EXPECT_NO_THROW(check_checkpoint_fits(c, "ck.bin", scene, run_of(scene)));
  auto refused = [&](const Scene& other, const std::string& fragment) {
    try {
      check_checkpoint_fits(c, "ck.bin", other, run_of(other));
      ADD_FAILURE() << "accepted; expected '" << fragment << "'";
    } catch (const RunError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  Scene other = scene;
  other.simulation.periodic.x->hi = 8;
  refused(other, "periodic_x = [-1, 7], this run has [-1, 8]");
  other = scene;
  other.simulation.periodic.y.reset();
  other.simulation.periodic.shear_rate = 0;
  refused(other, "periodic_y = [-1, 7], this run has none");
  other = scene;
  other.simulation.periodic.shear_rate = 3;
  refused(other, "shear_rate = 2, this run has 3");
  other = scene;
  other.simulation.periodic = PeriodicCell{};
  refused(other, "periodic_x = [-1, 7], which this run does not have");
  // And a checkpoint of a run without a cell does not continue in one.
  Scene plain = scene;
  plain.simulation.periodic = PeriodicCell{};
  c.meta = run_of(plain);
  refused(scene, "does not record [simulation] periodic_x");
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
