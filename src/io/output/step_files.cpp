#include "io/output/step_files.hpp"

#include "tridem/output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <system_error>

namespace tridem::io {

namespace fs = std::filesystem;

std::string StepFiles::name(std::int64_t step, std::string_view extension) const {
  return fmt::format("{}{:09}{}", prefix, step, extension);
}

fs::path StepFiles::path(const fs::path& dir, std::int64_t step, std::string_view extension) const {
  return dir / folder / name(step, extension);
}

std::optional<std::int64_t> StepFiles::step_of(std::string_view file_name,
                                               std::string_view extension) const {
  if (file_name.size() <= prefix.size() + extension.size() || !file_name.starts_with(prefix) ||
      !file_name.ends_with(extension))
    return std::nullopt;
  const std::string_view digits =
      file_name.substr(prefix.size(), file_name.size() - prefix.size() - extension.size());
  if (!std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return std::nullopt;
  std::int64_t step = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), step);
  if (ec != std::errc() || end != digits.data() + digits.size()) return std::nullopt;
  return step;
}

void StepFiles::remove(const fs::path& dir, std::string_view extension,
                       std::optional<std::int64_t> after) const {
  std::error_code ec;
  const fs::path where = dir / folder;
  if (!fs::is_directory(where, ec)) return;
  for (const auto& entry : fs::directory_iterator(where, ec)) {
    const auto step = step_of(entry.path().filename().string(), extension);
    if (step && (!after || *step > *after)) fs::remove(entry.path(), ec);
  }
}

std::vector<fs::path> StepFiles::all(const fs::path& dir, std::string_view extension) const {
  std::vector<std::pair<std::int64_t, fs::path>> found;
  std::error_code ec;
  const fs::path where = dir / folder;
  if (fs::is_directory(where, ec))
    for (const auto& entry : fs::directory_iterator(where, ec))
      if (const auto step = step_of(entry.path().filename().string(), extension))
        found.emplace_back(*step, entry.path());
  std::sort(found.begin(), found.end());
  std::vector<fs::path> out;
  out.reserve(found.size());
  for (auto& f : found) out.push_back(std::move(f.second));
  return out;
}

std::optional<fs::path> StepFiles::last(const fs::path& dir, std::string_view extension) const {
  std::optional<fs::path> found;
  std::int64_t highest = -1;
  std::error_code ec;
  const fs::path where = dir / folder;
  if (!fs::is_directory(where, ec)) return found;
  for (const auto& entry : fs::directory_iterator(where, ec)) {
    const auto step = step_of(entry.path().filename().string(), extension);
    if (step && *step > highest) {
      highest = *step;
      found = entry.path();
    }
  }
  return found;
}

}  // namespace tridem::io

namespace tridem {

std::string frame_file_name(std::int64_t step) { return io::kFrameFiles.name(step, ".vtu"); }

std::string contacts_file_stem(std::int64_t step) { return io::kContactFiles.name(step, ""); }

std::optional<std::filesystem::path> last_frame_file(const std::filesystem::path& dir) {
  return io::kFrameFiles.last(dir, ".vtu");
}

}  // namespace tridem
