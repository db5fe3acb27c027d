// The chunk policy of the time loop. Regression: with output events every few steps the
// chunks were cut short yet doubled every time, the length overflowed after 63 events and
// the run stalled at that step forever (seen at step 27 500 with every = 500).
#include "core/chunk_size.hpp"

#include <gtest/gtest.h>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

TEST(ChunkSize, CutShortChunksDoNotGrow) {
  std::int64_t chunk = 1;
  for (int event = 0; event < 1000; ++event) chunk = next_chunk(chunk, 1, 1e-6);
  EXPECT_EQ(chunk, 2) << "only the first, full chunk may double";
}

TEST(ChunkSize, FullQuickChunksGrowToTheCapAndNoFurther) {
  std::int64_t chunk = 1;
  for (int i = 0; i < 200; ++i) chunk = next_chunk(chunk, chunk, 1e-6);
  EXPECT_EQ(chunk, kMaxChunk);
}

TEST(ChunkSize, SlowChunksShrinkToOne) {
  std::int64_t chunk = 1024;
  for (int i = 0; i < 50; ++i) chunk = next_chunk(chunk, chunk, 1.0);
  EXPECT_EQ(chunk, 1);
  EXPECT_EQ(next_chunk(8, 8, 0.1), 8);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
