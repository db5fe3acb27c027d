// Checkpoint files: exact round trip, and refusal with a message (never a crash, never a
// wrong state) of every truncation, flipped bits, another format, scene or precision.
#include "io/checkpoint/crc32.hpp"
#include "support/scene_builder.hpp"
#include "tridem/checkpoint.hpp"
#include "tridem/error.hpp"
#include "unit/io/io_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace tridem {
namespace {

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
  return c;
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
  // slips per pair, before the contact of issue 10), and the next one (5), with a
  // consistent header checksum: refused for the version, not as damage.
  Checkpoint c = sample_checkpoint();
  auto bytes = encode_checkpoint(c);
  for (const int version : {1, 2, 3, 5}) {
    bytes[8] = static_cast<std::uint8_t>(version);
    const std::uint32_t crc = io::crc32(std::span(bytes).first(44));  // as the writer does
    for (int k = 0; k < 4; ++k) bytes[44 + k] = static_cast<std::uint8_t>(crc >> (8 * k));
    expect_refused(bytes, "checkpoint format version " + std::to_string(version) +
                              "; this tridem reads version 4");
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

}  // namespace
}  // namespace tridem
