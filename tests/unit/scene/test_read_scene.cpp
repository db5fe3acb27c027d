// read_scene: what reaching the disk adds to parse_scene (missing files, paths in messages).
#include "tridem/error.hpp"
#include "tridem/scene_io.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

std::string refusal_of(const std::filesystem::path& file) {
  try {
    read_scene(file);
  } catch (const SceneError& e) {
    return e.what();
  }
  ADD_FAILURE() << "read_scene accepted " << file;
  return {};
}

TEST(SceneRead, NonexistentFileNamesThePath) {
  const auto missing = std::filesystem::temp_directory_path() / "tridem-no-such-scene.toml";
  const std::string message = refusal_of(missing);
  EXPECT_NE(message.find(missing.string()), std::string::npos) << message;
  EXPECT_NE(message.find("no such file"), std::string::npos) << message;
}

TEST(SceneRead, DirectoryIsRefused) {
  const std::string message = refusal_of(std::filesystem::temp_directory_path());
  EXPECT_NE(message.find("directory"), std::string::npos) << message;
}

TEST(SceneRead, MessagesCarryThePathAndLine) {
  // A random name so that concurrent test runs don't share the file.
  const auto file = std::filesystem::temp_directory_path() /
                    ("tridem-scene-test-" + std::to_string(std::random_device{}()) + ".toml");
  {
    std::ofstream out(file);
    out << "[simulation]\nsteps = 5\n\n[[material]]\nname = \"m\"\ndensity = -1\n";
  }
  const std::string message = refusal_of(file);
  std::filesystem::remove(file);
  EXPECT_NE(message.find(file.string() + ":6:"), std::string::npos) << message;
  EXPECT_NE(message.find("key 'density'"), std::string::npos) << message;
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
