#include "io/output/out_file.hpp"

#include "tridem/error.hpp"

#include <cerrno>
#include <cstring>

namespace tridem::io {

OutFile::OutFile(std::filesystem::path path, Mode mode) : path_(std::move(path)) {
  file_ = std::fopen(path_.c_str(), mode == Mode::Append ? "ab" : "wb");
  if (!file_) fail("cannot create");
}

OutFile::~OutFile() {
  if (file_) std::fclose(file_);
}

OutFile::OutFile(OutFile&& other) noexcept
    : path_(std::move(other.path_)),
      file_(std::exchange(other.file_, nullptr)),
      buffer_(std::move(other.buffer_)) {}

OutFile& OutFile::operator=(OutFile&& other) noexcept {
  if (this != &other) {
    if (file_) std::fclose(file_);
    path_ = std::move(other.path_);
    file_ = std::exchange(other.file_, nullptr);
    buffer_ = std::move(other.buffer_);
  }
  return *this;
}

void OutFile::write(std::string_view text) {
  buffer_.append(text.data(), text.data() + text.size());
  if (buffer_.size() >= kChunk) drain();
}

void OutFile::drain() {
  if (!file_)
    throw RunError(fmt::format("cannot write '{}': already closed", path_.string()));
  if (buffer_.size() != 0 &&
      std::fwrite(buffer_.data(), 1, buffer_.size(), file_) != buffer_.size())
    fail("cannot write");
  buffer_.clear();
}

void OutFile::flush() {
  drain();
  if (std::fflush(file_) != 0) fail("cannot write");
}

void OutFile::close() {
  flush();
  // fclose can still report a deferred write error (NFS, full disk), so it is checked.
  const int rc = std::fclose(std::exchange(file_, nullptr));
  if (rc != 0) fail("cannot close");
}

void OutFile::fail(const char* doing) const {
  const int code = errno;
  throw RunError(fmt::format("{} '{}': {}", doing, path_.string(),
                             code ? std::strerror(code) : "unknown error"));
}

}  // namespace tridem::io
