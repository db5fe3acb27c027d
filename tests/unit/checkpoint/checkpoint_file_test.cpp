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
  c.meta = {Precision::Float, 0x0123456789ABCDEFull};
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
  s.pair_slip = {{1e-9, -0.0, 0, 0, 0, 2e-7}, {0, 0, 0, 1, 0, 0}, {-3e-8, 0, 0, 0, 0, 0}};
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
  payload.back() ^= 1;
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
  // The next version (3) with a consistent header checksum, and the last one before the
  // energy arrays (1): refused for the version, not as damage.
  Checkpoint c = sample_checkpoint();
  auto bytes = encode_checkpoint(c);
  bytes[8] = 1;
  {
    const std::uint32_t crc = io::crc32(std::span(bytes).first(44));
    for (int k = 0; k < 4; ++k) bytes[44 + k] = static_cast<std::uint8_t>(crc >> (8 * k));
    expect_refused(bytes, "checkpoint format version 1; this tridem reads version 2");
  }
  bytes[8] = 3;
  const std::uint32_t crc = io::crc32(std::span(bytes).first(44));  // as the writer does
  for (int k = 0; k < 4; ++k) bytes[44 + k] = static_cast<std::uint8_t>(crc >> (8 * k));
  expect_refused(bytes, "version 3");
}

TEST(CheckpointFile, ValidFileOfAnotherSceneOrPrecisionIsRefused) {
  Scene scene = test::empty_scene();
  scene.triangles.push_back(test::triangle({0, 0}, {1, 0}, {0, 1}));
  scene.triangles.push_back(test::triangle({2, 0}, {3, 0}, {2, 1}));
  scene.triangles.push_back(test::triangle({4, 0}, {5, 0}, {4, 1}));
  Checkpoint c = sample_checkpoint();
  c.meta = {Precision::Double, scene_fingerprint(scene)};
  EXPECT_NO_THROW(check_checkpoint_fits(c, "ck.bin", scene, Precision::Double));

  auto refused = [&](const Scene& other, Precision p, const std::string& fragment) {
    try {
      check_checkpoint_fits(c, "ck.bin", other, p);
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
  Scene stiffer = scene;  // contact parameters may change between runs
  stiffer.materials[0].penalty *= 10;
  EXPECT_NO_THROW(check_checkpoint_fits(c, "ck.bin", stiffer, Precision::Double));
}

}  // namespace
}  // namespace tridem
