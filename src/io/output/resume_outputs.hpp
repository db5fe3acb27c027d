#pragma once
// Taking over the outputs of an interrupted run, so that a restarted one continues them:
// everything written after the checkpoint's step (log rows, frames, contact files) is
// removed, as the restarted run will write it again, bit for bit.
#include <cstdint>
#include <filesystem>
#include <string_view>

namespace tridem::io {

/// Keeps the header and the rows of `file` whose step (first field) is <= `step`; a last
/// line without its newline (a write cut short) goes too. Creates the file with `header`
/// if it does not exist. The file is replaced atomically.
void trim_log(const std::filesystem::path& file, std::string_view header, std::int64_t step);

/// Removes frames/frame_<s>.vtu and contacts/contacts_<s>.{csv,vtp} with s > `step`.
void remove_frames_after(const std::filesystem::path& dir, std::int64_t step);

}  // namespace tridem::io
