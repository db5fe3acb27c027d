// Atomic replacement: a write that fails part-way (the test hook stands in for a kill or
// a full disk) leaves the previous checkpoint whole and loadable, and no temporary file.
#include "io/output/atomic_file.hpp"
#include "tridem/checkpoint.hpp"
#include "tridem/error.hpp"
#include "unit/io/io_test_support.hpp"

#include <gtest/gtest.h>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

Checkpoint checkpoint_at(std::int64_t step, std::size_t particles) {
  Checkpoint c;
  c.state.step = step;
  for (auto* v : {&c.state.x, &c.state.y, &c.state.theta, &c.state.vx, &c.state.vy,
                  &c.state.omega})
    v->assign(particles, static_cast<double>(step));
  return c;
}

TEST(AtomicCheckpoint, FailureMidWriteKeepsThePreviousCheckpoint) {
  test::TempDir dir;
  const auto file = dir.path() / "checkpoint.ckpt";
  write_checkpoint(file, checkpoint_at(100, 50));
  const auto newer = encode_checkpoint(checkpoint_at(200, 50));
  for (std::size_t cut : {std::size_t{0}, std::size_t{10}, newer.size() / 2, newer.size() - 1}) {
    EXPECT_THROW(io::write_file_atomically(file, newer, io::WriteFault{cut}), RunError)
        << "cut at " << cut;
    const Checkpoint kept = read_checkpoint(file);
    EXPECT_EQ(kept.state.step, 100) << "cut at " << cut;
    EXPECT_FALSE(std::filesystem::exists(io::temporary_path(file))) << "cut at " << cut;
  }
  io::write_file_atomically(file, newer);
  EXPECT_EQ(read_checkpoint(file).state.step, 200);
}

TEST(AtomicCheckpoint, FailureNamesTheFile) {
  test::TempDir dir;
  const auto file = dir.path() / "no_such_folder" / "checkpoint.ckpt";
  try {
    write_checkpoint(file, checkpoint_at(1, 2));
    ADD_FAILURE() << "wrote into a missing folder";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_folder"), std::string::npos) << e.what();
  }
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
