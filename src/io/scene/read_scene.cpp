// Reading a scene file from disk; parsing is parse_scene's job.
#include "tridem/error.hpp"
#include "tridem/scene_io.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

namespace tridem {

Scene read_scene(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::error_code ec;
  if (!std::filesystem::exists(file, ec))
    throw SceneError(fmt::format("{}: cannot read scene file: no such file", name));
  if (std::filesystem::is_directory(file, ec))
    throw SceneError(fmt::format("{}: cannot read scene file: it is a directory", name));
  std::ifstream in(file, std::ios::binary);
  if (!in)
    throw SceneError(fmt::format("{}: cannot open scene file: {}", name, std::strerror(errno)));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad())
    throw SceneError(fmt::format("{}: error while reading scene file: {}", name,
                                 std::strerror(errno)));
  return parse_scene(text.str(), name);
}

}  // namespace tridem
