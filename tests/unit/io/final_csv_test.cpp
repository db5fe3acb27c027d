#include "io_test_support.hpp"
#include "tridem/error.hpp"
#include "tridem/output.hpp"

#include <gtest/gtest.h>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

TEST(FinalCsv, HeaderAndRowsRoundTrip) {
  test::TempDir tmp;
  const Snapshot s = test::sample_snapshot();
  write_final_csv(tmp.path() / "final.csv", s);

  const auto lines = test::read_lines(tmp.path() / "final.csv");
  ASSERT_EQ(lines.size(), 1 + s.size());
  EXPECT_EQ(lines[0], "id,x,y,theta,vx,vy,omega,x1,y1,x2,y2,x3,y3,body");
  for (std::size_t k = 0; k < s.size(); ++k) {
    const std::vector<double> row = test::numbers(lines[1 + k]);
    const std::vector<double> expected = {double(k), s.x[k],     s.y[k],  s.theta[k], s.vx[k],
                                          s.vy[k],   s.omega[k], s.x1[k], s.y1[k],    s.x2[k],
                                          s.y2[k],   s.x3[k],    s.y3[k], double(k)};
    // %.17g round-trips exactly; without bodies each triangle is its own body.
    EXPECT_EQ(row, expected) << "row " << k;
  }
}

TEST(FinalCsv, InconsistentSnapshotIsRefused) {
  test::TempDir tmp;
  Snapshot s = test::sample_snapshot();
  s.omega.pop_back();
  EXPECT_THROW(write_final_csv(tmp.path() / "final.csv", s), Error);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
