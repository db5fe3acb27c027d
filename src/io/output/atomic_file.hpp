#pragma once
// Replacing a file so that a crash, a kill or a full disk at any moment leaves either the
// old file or the whole new one: write a temporary file beside it, fsync it, rename it
// over the old one (atomic within a directory), then fsync the directory so the rename
// itself survives a power cut.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <span>

namespace tridem::io {

/// A test hook: the write fails, as a full disk or a kill would, after this many bytes.
struct WriteFault {
  std::size_t fail_after_bytes = std::numeric_limits<std::size_t>::max();
};

/// Throws RunError naming `file` and the system's reason on failure; the old file is then
/// untouched and the temporary one removed.
void write_file_atomically(const std::filesystem::path& file,
                           std::span<const std::uint8_t> bytes, const WriteFault& fault = {});

/// The temporary file write_file_atomically uses for `file`.
std::filesystem::path temporary_path(const std::filesystem::path& file);

/// The last move of write_file_atomically, for a temporary file written and synced by other
/// means (the MPI ranks' checkpoint): renames temporary_path(file) over `file` and syncs
/// the directory. Throws RunError naming `file` and the system's reason.
void replace_with_temporary(const std::filesystem::path& file);

}  // namespace tridem::io
