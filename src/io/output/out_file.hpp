#pragma once
// A file being written, with the one error policy of all output: any failure to open,
// write or flush throws RunError naming the path and the system's reason. Text is
// gathered in a buffer and handed to stdio in large pieces, so per-row formatting with
// fmt costs no system calls.
#include <fmt/format.h>

#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string_view>
#include <utility>

namespace tridem::io {

class OutFile {
 public:
  enum class Mode { Truncate, Append };
  /// Creates or truncates the file, or appends to it (a restarted run's logs).
  explicit OutFile(std::filesystem::path path, Mode mode = Mode::Truncate);
  ~OutFile();  ///< closes without reporting; call close() where errors must surface
  OutFile(OutFile&&) noexcept;
  OutFile& operator=(OutFile&&) noexcept;
  OutFile(const OutFile&) = delete;
  OutFile& operator=(const OutFile&) = delete;

  template <class... Args>
  void print(fmt::format_string<Args...> format, Args&&... args) {
    fmt::format_to(fmt::appender(buffer_), format, std::forward<Args>(args)...);
    if (buffer_.size() >= kChunk) drain();
  }
  void write(std::string_view text);

  /// Appends what rows(buffer, first, last) formats for rows [first, last) of 0..count-1,
  /// byte for byte as one call over all rows would: blocks of rows are formatted on the
  /// OpenMP threads, into buffers of their own, and written in row order. A 10^7-row
  /// final.csv is some 2 GB of text; formatting it on one core took most of a large run's
  /// final output.
  using RowBlock = std::function<void(fmt::memory_buffer&, std::size_t, std::size_t)>;
  void print_rows(std::size_t count, const RowBlock& rows);

  /// Pushes everything written so far to the operating system.
  void flush();
  void close();

  const std::filesystem::path& path() const { return path_; }

 private:
  static constexpr std::size_t kChunk = 1 << 16;
  void drain();
  [[noreturn]] void fail(const char* doing) const;

  std::filesystem::path path_;
  std::FILE* file_ = nullptr;
  fmt::memory_buffer buffer_;
};

}  // namespace tridem::io
