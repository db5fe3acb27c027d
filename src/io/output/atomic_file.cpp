#include "io/output/atomic_file.hpp"

#include "tridem/error.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

namespace tridem::io {

namespace {

[[noreturn]] void fail(const char* doing, const std::filesystem::path& path, int code) {
  throw RunError(fmt::format("{} '{}': {}", doing, path.string(), std::strerror(code)));
}

/// Closes the descriptor and removes the temporary file unless the write completed.
class TemporaryFile {
 public:
  explicit TemporaryFile(std::filesystem::path path) : path_(std::move(path)) {
    fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd_ < 0) fail("cannot create", path_, errno);
  }
  ~TemporaryFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!kept_) ::unlink(path_.c_str());
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  void write(std::span<const std::uint8_t> bytes, const WriteFault& fault) {
    std::size_t done = 0;
    while (done < bytes.size()) {
      if (done >= fault.fail_after_bytes)
        throw RunError(fmt::format("cannot write '{}': simulated failure after {} bytes",
                                   path_.string(), done));
      const std::size_t limit = std::min(bytes.size(), fault.fail_after_bytes);
      const ssize_t wrote = ::write(fd_, bytes.data() + done, std::min<std::size_t>(limit - done, 1 << 20));
      if (wrote < 0 && errno == EINTR) continue;
      if (wrote <= 0) fail("cannot write", path_, wrote < 0 ? errno : ENOSPC);
      done += static_cast<std::size_t>(wrote);
    }
  }
  /// Data on disk, descriptor closed: ready to be renamed.
  void sync_and_close() {
    if (::fsync(fd_) != 0) fail("cannot sync", path_, errno);
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) fail("cannot close", path_, errno);
  }
  void keep() { kept_ = true; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  bool kept_ = false;
};

void sync_directory(const std::filesystem::path& dir) {
  const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;  // best effort: some file systems cannot open a directory
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

std::filesystem::path temporary_path(const std::filesystem::path& file) {
  std::filesystem::path temporary = file;
  temporary += ".tmp";
  return temporary;
}

void write_file_atomically(const std::filesystem::path& file,
                           std::span<const std::uint8_t> bytes, const WriteFault& fault) {
  TemporaryFile temporary(temporary_path(file));
  temporary.write(bytes, fault);
  temporary.sync_and_close();
  replace_with_temporary(file);
  temporary.keep();
}

void replace_with_temporary(const std::filesystem::path& file) {
  if (std::rename(temporary_path(file).c_str(), file.c_str()) != 0)
    fail("cannot replace", file, errno);
  sync_directory(file.parent_path());
}

}  // namespace tridem::io
