#include "mpi/shared_file.hpp"

#include "io/output/atomic_file.hpp"
#include "mpi/agreement.hpp"
#include "tridem/error.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace tridem::mpi {

namespace {

std::string mpi_reason(int code) {
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  if (MPI_Error_string(code, text, &length) != MPI_SUCCESS)
    return fmt::format("MPI error {}", code);
  return std::string(text, static_cast<std::size_t>(length));
}

}  // namespace

SharedFile::SharedFile(MPI_Comm comm, std::filesystem::path file, std::uint64_t size)
    : comm_(comm), file_(std::move(file)), temporary_(io::temporary_path(file_)) {
  MPI_Comm_rank(comm_, &rank_);
  // MPI_MODE_CREATE keeps an old temporary file's bytes: the size is set below.
  const int opened = MPI_File_open(comm_, temporary_.c_str(), MPI_MODE_CREATE | MPI_MODE_WRONLY,
                                   MPI_INFO_NULL, &handle_);
  if (opened != MPI_SUCCESS) {
    handle_ = MPI_FILE_NULL;
    problem_ = fmt::format("cannot create '{}': {}", temporary_.string(), mpi_reason(opened));
  }
  agree_or_throw();
  const int sized = MPI_File_set_size(handle_, static_cast<MPI_Offset>(size));
  if (sized != MPI_SUCCESS)
    problem_ = fmt::format("cannot size '{}' to {} bytes: {}", temporary_.string(), size,
                           mpi_reason(sized));
  if (auto message = agree(comm_, problem_)) {
    discard();  // no destructor runs for a constructor that throws
    throw RunError(*message);
  }
}

SharedFile::~SharedFile() {
  if (!committed_) discard();
}

void SharedFile::discard() {
  close();
  if (rank_ == 0) {
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
  }
}

void SharedFile::write_at(std::uint64_t offset, std::span<const std::uint8_t> bytes) {
  // MPI counts are ints: a large piece goes in chunks of 1 GiB.
  constexpr std::size_t kChunk = std::size_t{1} << 30;
  for (std::size_t done = 0; done < bytes.size() && !problem_; done += kChunk) {
    const std::size_t count = std::min(kChunk, bytes.size() - done);
    const std::uint64_t at = offset + done;
    MPI_Status status;
    const int wrote = MPI_File_write_at(handle_, static_cast<MPI_Offset>(at), bytes.data() + done,
                                        static_cast<int>(count), MPI_BYTE, &status);
    int written = 0;
    if (wrote == MPI_SUCCESS) MPI_Get_count(&status, MPI_BYTE, &written);
    if (wrote != MPI_SUCCESS || static_cast<std::size_t>(written) != count)
      problem_ = fmt::format("cannot write '{}': {}", temporary_.string(),
                             wrote != MPI_SUCCESS ? mpi_reason(wrote)
                                                  : fmt::format("{} of {} bytes written at byte {}",
                                                                written, count, at));
  }
}

void SharedFile::commit() {
  agree_or_throw();
  const int synced = MPI_File_sync(handle_);
  if (synced != MPI_SUCCESS)
    problem_ = fmt::format("cannot sync '{}': {}", temporary_.string(), mpi_reason(synced));
  agree_or_throw();
  close();
  if (rank_ == 0) {
    try {
      io::replace_with_temporary(file_);
    } catch (const RunError& e) {
      problem_ = e.what();
    }
  }
  agree_or_throw();
  committed_ = true;
}

void SharedFile::agree_or_throw() {
  if (auto message = agree(comm_, problem_)) throw RunError(*message);
}

void SharedFile::close() {
  if (handle_ == MPI_FILE_NULL) return;
  MPI_File_close(&handle_);
  handle_ = MPI_FILE_NULL;
}

}  // namespace tridem::mpi
