#pragma once
// One file written by every rank of a communicator side by side, through MPI-IO (ROMIO or
// OMPIO pick what the file system does best: Lustre stripes, GPFS, NFS, a local disk), and
// replaced as io::write_file_atomically replaces a file: into the temporary file beside it,
// synced, then renamed over the old one by rank 0. A crash at any moment leaves the old
// file or the whole new one. A failure on any rank is agreed: every rank throws RunError
// with the lowest failing rank's message, and the temporary file is removed.
#include <cstdint>
#include <filesystem>
#include <mpi.h>
#include <optional>
#include <span>
#include <string>

namespace tridem::mpi {

class SharedFile {
 public:
  /// Collective: creates the temporary file of `file` (io::temporary_path), `size` bytes.
  SharedFile(MPI_Comm comm, std::filesystem::path file, std::uint64_t size);
  ~SharedFile();  ///< collective unless committed: closes and removes the temporary file
  SharedFile(const SharedFile&) = delete;
  SharedFile& operator=(const SharedFile&) = delete;

  /// This rank's bytes at `offset` (not collective). A failure is kept for commit().
  void write_at(std::uint64_t offset, std::span<const std::uint8_t> bytes);
  /// Collective: syncs and closes the file, and rank 0 renames it over `file`.
  void commit();

 private:
  /// Every rank throws the lowest failing rank's message, if any failed (collective).
  void agree_or_throw();
  void close();
  /// Collective: closes the file and removes it.
  void discard();

  MPI_Comm comm_;
  std::filesystem::path file_, temporary_;
  MPI_File handle_ = MPI_FILE_NULL;
  int rank_ = 0;
  std::optional<std::string> problem_;
  bool committed_ = false;
};

}  // namespace tridem::mpi
