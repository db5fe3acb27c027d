#pragma once
// Taking over the logs of an interrupted run, so that a restarted one continues them:
// rows written after the checkpoint's step are removed, as the restarted run will write
// them again, bit for bit. (Frame files after it go by StepFiles::remove.)
#include <cstdint>
#include <filesystem>
#include <string_view>

namespace tridem::io {

/// Keeps the header and the rows of `file` whose step (first field) is <= `step`; a last
/// line without its newline (a write cut short) goes too. Creates the file with `header`
/// if it does not exist. The file is replaced atomically.
void trim_log(const std::filesystem::path& file, std::string_view header, std::int64_t step);

}  // namespace tridem::io
