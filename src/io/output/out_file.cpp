#include "io/output/out_file.hpp"

#include "tridem/error.hpp"

#include <omp.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <exception>
#include <vector>

namespace tridem::io {

namespace {
std::string_view to_view(const fmt::memory_buffer& text) { return {text.data(), text.size()}; }
}  // namespace

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
  // Windows of blocks, two in flight: the thread that hands out a window's blocks (as
  // tasks) writes the previous window's text meanwhile, so that the writing, one thread's
  // work, runs beside the formatting rather than after it (at 10^7 rows, gigabytes).
  const std::size_t window = 4 * static_cast<std::size_t>(threads);
  std::vector<fmt::memory_buffer> text(2 * window);
  std::exception_ptr error;
  const auto write_window = [&](std::size_t start) {
    const std::size_t end = std::min(blocks, start + window);
    for (std::size_t b = start; b < end; ++b) write(to_view(text[b % (2 * window)]));
  };
#pragma omp parallel num_threads(threads)
#pragma omp single
  {
    for (std::size_t start = 0; start < blocks && !error; start += window) {
      const std::size_t end = std::min(blocks, start + window);
      for (std::size_t b = start; b < end; ++b) {
#pragma omp task default(shared) firstprivate(b)
        {
          fmt::memory_buffer& out = text[b % (2 * window)];
          out.clear();
          try {
            rows(out, b * kBlockRows, std::min(count, (b + 1) * kBlockRows));
          } catch (...) {
#pragma omp critical(tridem_print_rows_error)
            if (!error) error = std::current_exception();
          }
        }
      }
      if (start > 0) {
        try {
          write_window(start - window);
        } catch (...) {
#pragma omp critical(tridem_print_rows_error)
          if (!error) error = std::current_exception();
        }
      }
#pragma omp taskwait
    }
  }
  if (error) std::rethrow_exception(error);
  write_window((blocks - 1) / window * window);
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
