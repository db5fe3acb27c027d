#include "io/output/out_file.hpp"

#include "tridem/error.hpp"

#include <omp.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <exception>
#include <vector>

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
  if (text.size() < kChunk) {
    buffer_.append(text.data(), text.data() + text.size());
    if (buffer_.size() >= kChunk) drain();
    return;
  }
  // A frame's encoded array (hundreds of megabytes at 10^7 triangles) goes to stdio as it
  // is, after what is buffered, rather than through one more copy.
  drain();
  if (std::fwrite(text.data(), 1, text.size(), file_) != text.size()) fail("cannot write");
}

void OutFile::print_rows(std::size_t count, const RowBlock& rows) {
  constexpr std::size_t kBlockRows = 4096;
  const std::size_t blocks = (count + kBlockRows - 1) / kBlockRows;
  const int threads = blocks > 1 ? std::max(1, omp_get_max_threads()) : 1;
  if (threads == 1) {
    for (std::size_t first = 0; first < count; first += kBlockRows) {
      rows(buffer_, first, std::min(count, first + kBlockRows));
      if (buffer_.size() >= kChunk) drain();
    }
    return;
  }
  // A window of blocks at a time keeps the text in memory to a few per thread.
  const std::size_t window = 4 * static_cast<std::size_t>(threads);
  std::vector<fmt::memory_buffer> text(window);
  for (std::size_t start = 0; start < blocks; start += window) {
    const std::size_t end = std::min(blocks, start + window);
    std::exception_ptr error;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (std::size_t b = start; b < end; ++b) {
      fmt::memory_buffer& out = text[b - start];
      out.clear();
      try {
        rows(out, b * kBlockRows, std::min(count, (b + 1) * kBlockRows));
      } catch (...) {
#pragma omp critical(tridem_print_rows_error)
        if (!error) error = std::current_exception();
      }
    }
    if (error) std::rethrow_exception(error);
    for (std::size_t b = start; b < end; ++b) {
      const fmt::memory_buffer& block = text[b - start];
      buffer_.append(block.data(), block.data() + block.size());
      if (buffer_.size() >= kChunk) drain();
    }
  }
}

void OutFile::drain() {
  if (!file_) throw RunError(fmt::format("cannot write '{}': already closed", path_.string()));
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
