// The live view serves only its embedded page: exact paths, nothing from the file system.
#include "live/live_assets.hpp"

#include <gtest/gtest.h>

namespace tridem::live {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

TEST(LiveAssets, ServesThePageByExactPath) {
  const auto index = find_asset("/");
  ASSERT_TRUE(index);
  EXPECT_NE(index->content_type.find("text/html"), std::string_view::npos);
  EXPECT_NE(index->body.find("<canvas id=\"canvas\""), std::string_view::npos);
  EXPECT_NE(index->body.find("/live.js"), std::string_view::npos);
  const auto js = find_asset("/live.js?v=2");  // a query string is ignored
  ASSERT_TRUE(js);
  EXPECT_NE(js->content_type.find("javascript"), std::string_view::npos);
  EXPECT_NE(js->body.find("webgl2"), std::string_view::npos);
  // Nothing is fetched from elsewhere: no http(s) URL in the page.
  for (const auto* a : {&*index, &*js}) {
    EXPECT_EQ(a->body.find("http://"), std::string_view::npos);
    EXPECT_EQ(a->body.find("https://"), std::string_view::npos);
  }
}

TEST(LiveAssets, NoOtherPathIsServed) {
  for (const char* path :
       {"", "index.html", "/index.html/", "/../../etc/passwd", "/etc/passwd", "/live.js/..",
        "//live.js", "/LIVE.JS", "/ws", "/favicon.ico", "/%2e%2e/CMakeLists.txt"})
    EXPECT_FALSE(find_asset(path)) << path;
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem::live
