#pragma once
// How the files a run writes at each frame are named: <dir>/<folder>/<prefix><step><ext>,
// the step padded to 9 digits so that names sort by step. The writers name their files by
// this rule and the clean-up of an earlier or interrupted run recognises them by it, so
// the two cannot drift apart.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tridem::io {

struct StepFiles {
  std::string_view folder;  ///< under the output directory
  std::string_view prefix;

  /// "frame_000000042.vtu" for step 42 and ".vtu".
  std::string name(std::int64_t step, std::string_view extension) const;
  std::filesystem::path path(const std::filesystem::path& dir, std::int64_t step,
                             std::string_view extension) const;
  /// The step of a file name of this kind ending in `extension`; none for any other name.
  std::optional<std::int64_t> step_of(std::string_view file_name, std::string_view extension) const;
  /// Removes the files of this kind ending in `extension` whose step is after `after`, or
  /// all of them; nothing else in the folder is touched.
  void remove(const std::filesystem::path& dir, std::string_view extension,
              std::optional<std::int64_t> after = std::nullopt) const;
  /// Every file of this kind ending in `extension`, in step order.
  std::vector<std::filesystem::path> all(const std::filesystem::path& dir,
                                         std::string_view extension) const;
  /// The file of this kind ending in `extension` with the highest step, or none.
  std::optional<std::filesystem::path> last(const std::filesystem::path& dir,
                                            std::string_view extension) const;
};

inline constexpr StepFiles kFrameFiles{"frames", "frame_"};
inline constexpr StepFiles kContactFiles{"contacts", "contacts_"};
inline constexpr StepFiles kBondFiles{"bonds", "bonds_"};

}  // namespace tridem::io
