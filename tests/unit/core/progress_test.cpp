// The progress bar: what it draws, and that it stays silent when disabled or early.
#include "core/progress.hpp"

#include <cstdio>
#include <gtest/gtest.h>
#include <string>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

std::string drawn(std::FILE* f) {
  std::fflush(f);
  std::rewind(f);
  std::string text;
  for (int c; (c = std::fgetc(f)) != EOF;) text.push_back(static_cast<char>(c));
  return text;
}

TEST(ProgressBar, DrawsFractionRateAndTimeLeft) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  ProgressBar bar(200, true, f, 0.0);
  bar.update(50);
  const std::string text = drawn(f);
  EXPECT_NE(text.find("25.0%"), std::string::npos) << text;
  EXPECT_NE(text.find("50/200 steps"), std::string::npos) << text;
  EXPECT_NE(text.find("steps/s"), std::string::npos) << text;
  EXPECT_NE(text.find("left"), std::string::npos) << text;
  std::fclose(f);
}

TEST(ProgressBar, SilentWhenDisabledOrBeforeTheQuietTime) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  ProgressBar off(100, false, f, 0.0);
  off.update(10);
  ProgressBar early(100, true, f, 60.0);
  early.update(10);
  early.finish();
  EXPECT_EQ(drawn(f), "");
  std::fclose(f);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
