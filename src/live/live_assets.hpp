#pragma once
// The page of the live view, compiled into the program (live_assets.cpp.in, filled by
// CMake from src/live/page/): served by exact path, never from the file system.
#include <optional>
#include <string_view>

namespace tridem::live {

struct Asset {
  std::string_view content_type;
  std::string_view body;
};

/// The asset of a request target ("/", "/index.html", "/live.js"; a query string is
/// ignored), or none.
std::optional<Asset> find_asset(std::string_view target);

}  // namespace tridem::live
