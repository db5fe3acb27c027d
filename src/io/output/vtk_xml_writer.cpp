#include "io/output/vtk_xml_writer.hpp"

#include "io/output/base64.hpp"
#include "tridem/error.hpp"

#include <omp.h>

#include <algorithm>
#include <array>
#include <bit>

namespace tridem::io {
namespace {

constexpr std::string_view type_name(VtkWord word) {
  switch (word) {
    case VtkWord::Float32: return "Float32";
    case VtkWord::Float64: return "Float64";
    case VtkWord::Int32: return "Int32";
    case VtkWord::Int64: return "Int64";
    case VtkWord::UInt8: return "UInt8";
  }
  return "?";
}

template <class T>
T load(const std::uint8_t* p) {
  T value;
  std::memcpy(&value, p, sizeof value);
  return value;
}

}  // namespace

std::string VtkXmlWriter::components_attribute(int components) {
  return fmt::format("NumberOfComponents=\"{}\"", components);
}

void VtkXmlWriter::begin_file(OutFile& out, std::string_view type) {
  appended_.clear();
  const char* order = std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
  out.print("<?xml version=\"1.0\"?>\n"
            "<VTKFile type=\"{}\" version=\"1.0\" byte_order=\"{}\" header_type=\"UInt64\"{}>\n",
            type, order,
            format_.compressed()
                ? fmt::format(" compressor=\"{}\"", compressor_name(format_.compression))
                : std::string());
}

void VtkXmlWriter::end_file(OutFile& out) {
  if (format_.encoding == Encoding::Appended && !appended_.empty()) {
    // VTK's layout: the raw bytes start after the underscore; each array's offset counts
    // from there.
    const Clock::time_point start = Clock::now();
    out.write("  <AppendedData encoding=\"raw\">\n   _");
    out.write(std::string_view(reinterpret_cast<const char*>(appended_.data()), appended_.size()));
    out.write("\n  </AppendedData>\n");
    seconds_.write += since(start);
  }
  const Clock::time_point start = Clock::now();
  out.write("</VTKFile>\n");
  out.close();
  seconds_.write += since(start);
}

void VtkXmlWriter::emit(OutFile& out, std::string_view name, VtkWord word,
                        std::string_view size_attribute, int indent) {
  out.print("{:{}}<DataArray type=\"{}\"", "", indent, type_name(word));
  if (!name.empty()) out.print(" Name=\"{}\"", name);
  if (format_.encoding == Encoding::Appended) {
    out.print(" {} format=\"appended\" offset=\"{}\"/>\n", size_attribute, appended_.size());
    const std::array<std::span<const std::uint8_t>, 2> parts = binary_parts(out);
    const Clock::time_point start = Clock::now();
    for (const std::span<const std::uint8_t> part : parts)
      appended_.insert(appended_.end(), part.begin(), part.end());
    seconds_.encode += since(start);
    return;
  }
  const bool binary = format_.encoding == Encoding::Binary;
  out.print(" {} format=\"{}\">\n", size_attribute, binary ? "binary" : "ascii");
  if (binary) {
    // Each part a base64 run of its own, as VTK's writer encodes them.
    const std::array<std::span<const std::uint8_t>, 2> parts = binary_parts(out);
    Clock::time_point start = Clock::now();
    text_.clear();
    for (const std::span<const std::uint8_t> part : parts)
      if (!part.empty()) base64_append(part, text_);
    seconds_.encode += since(start);
    start = Clock::now();
    out.write(text_);
    seconds_.write += since(start);
  } else {
    write_ascii(out, word);
  }
  out.print("\n{:{}}</DataArray>\n", "", indent);
}

std::array<std::span<const std::uint8_t>, 2> VtkXmlWriter::binary_parts(const OutFile& out) {
  if (!format_.compressed()) {
    const std::uint64_t count = raw_.size() - kCountBytes;
    std::memcpy(raw_.data(), &count, sizeof count);
    return {std::span<const std::uint8_t>(raw_), std::span<const std::uint8_t>()};
  }
  const std::size_t used = compress_raw(out);
  return {std::span(reinterpret_cast<const std::uint8_t*>(header_.data()),
                    header_.size() * sizeof(std::uint64_t)),
          std::span<const std::uint8_t>(compressed_.data(), used)};
}

std::size_t VtkXmlWriter::compress_raw(const OutFile& out) {
  const Clock::time_point start = Clock::now();
  const std::span<const std::uint8_t> data = std::span(raw_).subspan(kCountBytes);
  const std::size_t blocks = (data.size() + kBlockSize - 1) / kBlockSize;
  header_.assign(3 + blocks, 0);
  header_[0] = blocks;
  header_[1] = kBlockSize;
  // VTK's "size of the last block": the partial block's size, or 0 when every block is full
  // (VTK's own writer then writes the block size; both read back the same).
  header_[2] = data.size() % kBlockSize;
  // Each block is compressed on its own (that is VTK's format), so the blocks go to the
  // OpenMP threads, each into a slot of the largest size the compressor may need, then
  // closed up in order: compression is the slowest part of writing a frame.
  const VtkCompression compression = format_.compression;
  const int threads = blocks > 1 ? std::max(1, omp_get_max_threads()) : 1;
  while (compressors_.size() < static_cast<std::size_t>(threads))
    compressors_.emplace_back(compression);
  const std::size_t slot = compressors_.front().bound(kBlockSize);
  compressed_.resize(blocks * slot);
  const auto count = static_cast<std::ptrdiff_t>(blocks);
  int failure = 0;
#pragma omp parallel for num_threads(threads) schedule(dynamic, 4)
  for (std::ptrdiff_t b = 0; b < count; ++b) {
    const std::size_t begin = static_cast<std::size_t>(b) * kBlockSize;
    const std::size_t size = std::min(kBlockSize, data.size() - begin);
    int error = 0;
    header_[3 + static_cast<std::size_t>(b)] =
        compressors_[static_cast<std::size_t>(omp_get_thread_num())].compress(
            data.data() + begin, size, compressed_.data() + static_cast<std::size_t>(b) * slot,
            slot, error);
    if (error != 0) {
#pragma omp atomic write
      failure = error;
    }
  }
  if (failure != 0)
    throw RunError(fmt::format("cannot compress an array of '{}': {} error {}", out.path().string(),
                               compression == VtkCompression::Lzma ? "lzma" : "libdeflate",
                               failure));
  std::size_t used = 0;
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t length = header_[3 + b];
    if (used != b * slot)
      std::memmove(compressed_.data() + used, compressed_.data() + b * slot, length);
    used += length;
  }
  seconds_.compress += since(start);
  return used;
}

void VtkXmlWriter::write_ascii(OutFile& out, VtkWord word) {
  constexpr std::size_t kPerLine = 6;
  const std::uint8_t* p = raw_.data() + kCountBytes;
  const std::size_t bytes = raw_.size() - kCountBytes;
  const std::size_t size = word == VtkWord::Float32 || word == VtkWord::Int32 ? 4
                           : word == VtkWord::UInt8                           ? 1
                                                                              : 8;
  const std::size_t count = bytes / size;
  for (std::size_t k = 0; k < count; ++k, p += size) {
    switch (word) {
      // Enough digits to read back each value exactly in its own type.
      case VtkWord::Float32: out.print("{:.9g}", load<float>(p)); break;
      case VtkWord::Float64: out.print("{:.17g}", load<double>(p)); break;
      case VtkWord::Int32: out.print("{}", load<std::int32_t>(p)); break;
      case VtkWord::Int64: out.print("{}", load<std::int64_t>(p)); break;
      case VtkWord::UInt8: out.print("{}", static_cast<int>(*p)); break;
    }
    if (k + 1 < count) out.write((k + 1) % kPerLine == 0 ? "\n" : " ");
  }
}

void VtkXmlWriter::time_field_data(OutFile& out, std::int64_t step, double time, int indent) {
  constexpr std::string_view kOne = "NumberOfTuples=\"1\"";
  out.print("{:{}}<FieldData>\n", "", indent);
  pack<double>(1, [time](std::size_t) { return time; });
  emit(out, "TimeValue", VtkWord::Float64, kOne, indent + 2);
  pack<std::int64_t>(1, [step](std::size_t) { return step; });
  emit(out, "step", VtkWord::Int64, kOne, indent + 2);
  out.print("{:{}}</FieldData>\n", "", indent);
}

void VtkXmlWriter::line_set_vtp(const std::filesystem::path& file, std::int64_t step, double time,
                                std::size_t points,
                                const std::function<double(std::size_t)>& point_x,
                                const std::function<double(std::size_t)>& point_y,
                                std::size_t segments,
                                const std::function<std::int64_t(std::size_t)>& end_a,
                                const std::function<std::int64_t(std::size_t)>& end_b,
                                std::string_view cell_attributes,
                                const std::function<void(OutFile&)>& cell_data) {
  OutFile out(file);
  begin_file(out, "PolyData");
  out.write("  <PolyData>\n");
  time_field_data(out, step, time, 4);
  out.print("    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"0\" NumberOfLines=\"{}\" "
            "NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n",
            points, segments);
  out.write("      <Points>\n");
  reals(
      out, "Points", 3, 3 * points,
      [&](std::size_t k) {
        const std::size_t p = k / 3;
        switch (k % 3) {
          case 0: return point_x(p);
          case 1: return point_y(p);
          default: return 0.0;
        }
      },
      8);
  out.write("      </Points>\n      <Lines>\n");
  indices(
      out, "connectivity", 1, 2 * segments, points,
      [&](std::size_t k) { return k % 2 == 0 ? end_a(k / 2) : end_b(k / 2); }, 8);
  indices(
      out, "offsets", 1, segments, 2 * segments,
      [](std::size_t k) { return static_cast<std::int64_t>(2 * (k + 1)); }, 8);
  out.print("      </Lines>\n      <CellData {}>\n", cell_attributes);
  cell_data(out);
  out.write("      </CellData>\n    </Piece>\n  </PolyData>\n");
  end_file(out);
}

}  // namespace tridem::io
