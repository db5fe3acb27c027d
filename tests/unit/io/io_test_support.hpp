#pragma once
// Shared by the output tests: a small hand-made state and a scratch directory.
#include "tridem/snapshot.hpp"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace tridem::test {

/// Three particles: 0 and 1 free (materials 0 and 1, moving and spinning), 2 a fixed wall
/// below them, and two contacts (0 on 1, 0 on the wall). Values have long decimal
/// expansions so that lost precision shows.
Snapshot sample_snapshot();

/// A fresh directory under the system's temporary folder, removed with its contents.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

std::vector<std::string> read_lines(const std::filesystem::path&);
std::string read_file(const std::filesystem::path&);
/// Every regular file under `dir`, by its path relative to `dir`, with its contents; files
/// ending in `skip_extension` (e.g. ".ckpt") left out.
std::map<std::string, std::string> files_under(const std::filesystem::path& dir,
                                               const std::string& skip_extension = "");

/// Splits one CSV row into the text of its cells.
std::vector<std::string> cells(const std::string& row);
/// Splits one CSV row of numbers.
std::vector<double> numbers(const std::string& row);

}  // namespace tridem::test
