#include "io/output/out_file.hpp"
#include "io_test_support.hpp"
#include "tridem/error.hpp"
#include "tridem/output.hpp"

#include <atomic>
#include <gtest/gtest.h>

#include <fstream>
#include <omp.h>
#include <sstream>
#include <stdexcept>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

/// Runs `make` and checks that it throws RunError whose message names `path`.
template <class F>
void expect_run_error_naming(F make, const std::filesystem::path& path) {
  try {
    make();
    ADD_FAILURE() << "no RunError for " << path;
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
}

TEST(OutputSet, CreatesDirectoryAndWritesEveryFile) {
  test::TempDir tmp;
  const auto dir = tmp.path() / "nested" / "run";
  OutputSet out(OutputSettings{}, dir);
  EXPECT_EQ(out.dir(), dir);
  const Snapshot s = test::sample_snapshot();
  out.write_frame(s);
  out.log(s);
  out.write_final(s);
  for (const char* file : {"energy.csv", "walls.csv", "final.csv", "bodies.csv", "tridem.pvd",
                           "contacts.pvd", "frames/frame_000001200.vtu",
                           "contacts/contacts_000001200.csv", "contacts/contacts_000001200.vtp"})
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / file)) << file;
}

TEST(OutputSet, RemovesFilesOfAnEarlierRunAndNothingElse) {
  test::TempDir tmp;
  const auto dir = tmp.path() / "run";
  std::filesystem::create_directories(dir / "frames");
  std::filesystem::create_directories(dir / "contacts");
  for (const char* stale : {"frames/frame_000099999.vtu", "frames/frame_000099999.png",
                            "contacts/contacts_000099999.csv", "contacts/contacts_000099999.vtp",
                            "final.csv", "tridem.pvd", "last_good.ckpt", "checkpoint.ckpt"})
    std::ofstream(dir / stale) << "old";
  std::ofstream(dir / "notes.txt") << "mine";
  std::ofstream(dir / "frames" / "sketch.png") << "mine";
  OutputSet out(OutputSettings{}, dir);
  for (const char* stale : {"frames/frame_000099999.vtu", "frames/frame_000099999.png",
                            "contacts/contacts_000099999.csv", "contacts/contacts_000099999.vtp",
                            "final.csv", "last_good.ckpt"})
    EXPECT_FALSE(std::filesystem::exists(dir / stale)) << stale;
  EXPECT_TRUE(std::filesystem::exists(dir / "checkpoint.ckpt"));
  EXPECT_TRUE(std::filesystem::exists(dir / "notes.txt"));
  EXPECT_TRUE(std::filesystem::exists(dir / "frames" / "sketch.png"));
}

TEST(OutputSet, NoFramesLeaveNoFrameFolders) {
  test::TempDir tmp;
  OutputSet out(OutputSettings{}, tmp.path());
  out.log(test::sample_snapshot());
  EXPECT_FALSE(std::filesystem::exists(tmp.path() / "frames"));
  EXPECT_FALSE(std::filesystem::exists(tmp.path() / "tridem.pvd"));
}

TEST(OutputSet, ThrowsRunErrorForDirectoryUnderAFile) {
  test::TempDir tmp;
  const auto file = tmp.path() / "plain-file";
  std::ofstream(file) << "not a directory\n";
  expect_run_error_naming([&] { OutputSet(OutputSettings{}, file / "out"); }, file / "out");
  expect_run_error_naming([&] { OutputSet(OutputSettings{}, file); }, file);
}

TEST(OutputSet, ThrowsRunErrorWhenFramesCannotBeWritten) {
  test::TempDir tmp;
  OutputSet out(OutputSettings{}, tmp.path());
  // A regular file where the frames folder should go.
  std::ofstream(tmp.path() / "frames") << "in the way\n";
  expect_run_error_naming([&] { out.write_frame(test::sample_snapshot()); },
                          tmp.path() / "frames");
}

TEST(OutputSet, ThrowsRunErrorWhenFinalCsvCannotBeWritten) {
  test::TempDir tmp;
  OutputSet out(OutputSettings{}, tmp.path());
  std::filesystem::create_directory(tmp.path() / "final.csv");
  expect_run_error_naming([&] { out.write_final(test::sample_snapshot()); },
                          tmp.path() / "final.csv");
}

TEST(OutFile, FailedWriteIsReportedWithTheSystemReason) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full here";
  io::OutFile out("/dev/full");
  out.write("more than nothing\n");
  try {
    out.close();
    ADD_FAILURE() << "writing to /dev/full succeeded";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/full"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("No space left"), std::string::npos) << e.what();
  }
}

// Rows formatted on several threads come out in row order, byte for byte what one loop
// writes, for row counts below, at and across the 4096-row blocks.
TEST(OutFile, RowsFormattedInParallelAreWrittenInOrder) {
  test::TempDir tmp;
  const auto row = [](fmt::memory_buffer& text, std::size_t k) {
    fmt::format_to(fmt::appender(text), "{},{:.17g}\n", k, 1.0 / static_cast<double>(k + 1));
  };
  const int threads = omp_get_max_threads();
  for (int t : {1, 3}) {
    omp_set_num_threads(t);
    for (std::size_t n : {0, 1, 4095, 4096, 4097, 100000}) {
      const auto file = tmp.path() / "rows.csv";
      io::OutFile out(file);
      out.write("head\n");
      out.print_rows(n, [&](fmt::memory_buffer& text, std::size_t first, std::size_t last) {
        for (std::size_t k = first; k < last; ++k) row(text, k);
      });
      out.close();
      fmt::memory_buffer expected;
      fmt::format_to(fmt::appender(expected), "head\n");
      for (std::size_t k = 0; k < n; ++k) row(expected, k);
      std::ifstream in(file, std::ios::binary);
      std::stringstream got;
      got << in.rdbuf();
      EXPECT_EQ(got.str(), fmt::to_string(expected)) << n << " rows on " << t << " threads";
    }
  }
  omp_set_num_threads(threads);
}

// A write that fails while the threads format the next window of rows (the disk full in
// the middle of a large final.csv) reaches the caller with the system's reason, from the
// thread that writes, and no block is formatted after it is known.
TEST(OutFile, FailedWriteWhileRowsAreFormattedReachesTheCaller) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full here";
  const int threads = omp_get_max_threads();
  omp_set_num_threads(3);  // windows of 12 blocks of 4096 rows: 200 000 rows are 5 windows
  io::OutFile out("/dev/full");
  std::atomic<std::size_t> formatted{0};
  try {
    out.print_rows(200000, [&](fmt::memory_buffer& text, std::size_t first, std::size_t last) {
      for (std::size_t k = first; k < last; ++k)
        fmt::format_to(fmt::appender(text), "{},{}\n", k, 0.5 * static_cast<double>(k));
      formatted += last - first;
    });
    out.close();
    ADD_FAILURE() << "writing rows to /dev/full succeeded";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find("No space left"), std::string::npos) << e.what();
  }
  // The first window's write fails while the second is formatted; the third never starts.
  EXPECT_LE(formatted.load(), std::size_t{2 * 12 * 4096});
  omp_set_num_threads(threads);
}

// An exception in one thread's block reaches the caller (never escapes an OpenMP region).
TEST(OutFile, ErrorWhileFormattingRowsReachesTheCaller) {
  test::TempDir tmp;
  const int threads = omp_get_max_threads();
  omp_set_num_threads(3);
  io::OutFile out(tmp.path() / "rows.csv");
  EXPECT_THROW(out.print_rows(50000,
                              [](fmt::memory_buffer&, std::size_t first, std::size_t) {
                                if (first >= 20000) throw std::runtime_error("bad row");
                              }),
               std::runtime_error);
  omp_set_num_threads(threads);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
