#include "io/output/resume_outputs.hpp"

#include "io/output/atomic_file.hpp"
#include "tridem/error.hpp"

#include <charconv>
#include <fmt/format.h>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>

namespace tridem::io {

namespace fs = std::filesystem;

namespace {

/// The integer at the start of `text` up to `stop`, if it is all digits (and a sign).
bool leading_step(std::string_view text, char stop, std::int64_t& step) {
  const std::size_t end = text.find(stop);
  if (end == std::string_view::npos || end == 0) return false;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + end, step);
  return ec == std::errc() && ptr == text.data() + end;
}

}  // namespace

void trim_log(const fs::path& file, std::string_view header, std::int64_t step) {
  std::string kept(header);
  std::ifstream in(file, std::ios::binary);
  if (in) {
    std::stringstream whole;
    whole << in.rdbuf();
    const std::string text = whole.str();
    std::size_t at = text.find('\n');  // after the header
    while (at != std::string::npos && at + 1 < text.size()) {
      const std::size_t begin = at + 1;
      at = text.find('\n', begin);
      if (at == std::string::npos) break;  // a row cut short by the interruption
      const std::string_view row(text.data() + begin, at - begin + 1);
      std::int64_t row_step = 0;
      if (leading_step(row, ',', row_step) && row_step <= step) kept += row;
    }
  }
  write_file_atomically(file, {reinterpret_cast<const std::uint8_t*>(kept.data()), kept.size()});
}

}  // namespace tridem::io
