#pragma once
// The pieces every VTK XML file we write shares: the root element and data arrays in the
// run's VtkFormat. Binary arrays are base64, as VTK's own writer stores inline data:
// uncompressed, a UInt64 byte count followed by the raw values, encoded as one run;
// compressed (vtkZLibDataCompressor or vtkLZMADataCompressor), the header [number of
// blocks, block size, size of the last block, compressed size of each block] (UInt64s)
// encoded as one run, then the blocks, each compressed by zlib (or as an .xz stream) on its
// own, as a second run.
#include "io/output/block_compressor.hpp"
#include "io/output/out_file.hpp"
#include "tridem/output.hpp"

#include <array>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace tridem::io {

/// The value types of the arrays we write.
enum class VtkWord { Float32, Float64, Int32, Int64, UInt8 };

/// VTK's class of a compression, as a file's root names it (compressor="..."): what the
/// writer writes and the reader accepts.
constexpr std::string_view compressor_name(VtkCompression compression) {
  return compression == VtkCompression::Lzma ? "vtkLZMADataCompressor" : "vtkZLibDataCompressor";
}

/// Writes VTK XML files in one format. It keeps its buffers from array to array and from
/// file to file: a writer kept for a run allocates only for its first (or a larger) frame.
/// One thread at a time.
class VtkXmlWriter {
 public:
  /// VTK's default block size for compressed arrays.
  static constexpr std::size_t kBlockSize = 1 << 15;

  explicit VtkXmlWriter(VtkFormat format = {}) : format_(format) {}
  const VtkFormat& format() const { return format_; }

  /// Wall seconds this writer has spent in each phase of its arrays since it was made (or
  /// since reset_seconds): what a frame's time goes to, for tridem_frame_bench. A handful of
  /// clock reads an array.
  struct Seconds {
    double pack = 0;      ///< converting the values into the raw array (OpenMP threads)
    double compress = 0;  ///< compressing its blocks (OpenMP threads) and closing them up
    double encode = 0;    ///< base64 (OpenMP threads) or copying into the appended block
    double write = 0;     ///< handing the text to the file (one thread)
  };
  const Seconds& seconds() const { return seconds_; }
  void reset_seconds() { seconds_ = {}; }

  /// Opens `<VTKFile type="...">` after the XML declaration, with the host's byte order
  /// and, when compressing, the compressor.
  void begin_file(OutFile&, std::string_view type);
  /// Closes the file's root, after the appended arrays' block in the appended encoding,
  /// and then the file (OutFile::close: errors surface).
  void end_file(OutFile&);

  /// A real-valued `<DataArray>` of `count` = components × tuples numbers value(k), as
  /// Float32 or Float64 by the format's precision.
  template <class Value>
  void reals(OutFile& out, std::string_view name, int components, std::size_t count,
             const Value& value, int indent) {
    if (format_.precision == VtkPrecision::Float32)
      pack<float>(count, value);
    else
      pack<double>(count, value);
    emit(out, name,
         format_.precision == VtkPrecision::Float32 ? VtkWord::Float32 : VtkWord::Float64,
         components_attribute(components), indent);
  }
  void reals(OutFile& out, std::string_view name, std::span<const double> values, int indent) {
    reals(
        out, name, 1, values.size(), [&](std::size_t k) { return values[k]; }, indent);
  }

  /// An integer `<DataArray>` of type T (std::int32_t, std::int64_t or std::uint8_t).
  template <class T, class Value>
  void integers(OutFile& out, std::string_view name, int components, std::size_t count,
                const Value& value, int indent) {
    pack<T>(count, value);
    emit(out, name, word_of<T>(), components_attribute(components), indent);
  }

  /// An array of indices or counts, none above `largest`: Int32 when they fit (half the
  /// bytes of Int64 before compression), Int64 otherwise.
  template <class Value>
  void indices(OutFile& out, std::string_view name, int components, std::size_t count,
               std::size_t largest, const Value& value, int indent) {
    if (largest <= static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
      integers<std::int32_t>(out, name, components, count, value, indent);
    else
      integers<std::int64_t>(out, name, components, count, value, indent);
  }

  /// `<FieldData>` with TimeValue (Float64 whatever the precision: ParaView shows it as
  /// the dataset's time) and step (Int64).
  void time_field_data(OutFile&, std::int64_t step, double time, int indent);

  /// A PolyData file of separate line segments between `points` (x, y each; z is 0):
  /// segment k joins points end_a(k) and end_b(k); `cell_data` writes its per-segment
  /// arrays inside `<CellData cell_attributes>` (e.g. `Scalars="damage"`), at indent 8.
  void line_set_vtp(const std::filesystem::path& file, std::int64_t step, double time,
                    std::size_t points, const std::function<double(std::size_t)>& point_x,
                    const std::function<double(std::size_t)>& point_y, std::size_t segments,
                    const std::function<std::int64_t(std::size_t)>& end_a,
                    const std::function<std::int64_t(std::size_t)>& end_b,
                    std::string_view cell_attributes,
                    const std::function<void(OutFile&)>& cell_data);

 private:
  static constexpr std::size_t kCountBytes = sizeof(std::uint64_t);
  using Clock = std::chrono::steady_clock;
  static double since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
  }

  template <class T>
  static constexpr VtkWord word_of() {
    if constexpr (std::is_same_v<T, float>)
      return VtkWord::Float32;
    else if constexpr (std::is_same_v<T, double>)
      return VtkWord::Float64;
    else if constexpr (std::is_same_v<T, std::int32_t>)
      return VtkWord::Int32;
    else if constexpr (std::is_same_v<T, std::int64_t>)
      return VtkWord::Int64;
    else {
      static_assert(std::is_same_v<T, std::uint8_t>);
      return VtkWord::UInt8;
    }
  }
  static std::string components_attribute(int components);

  /// Arrays of at least this many values are converted on the OpenMP threads: a frame of
  /// 10^6 triangles is some 10^8 values, which one core took most of a second to convert.
  static constexpr std::size_t kParallelValues = std::size_t{1} << 16;

  /// The values, converted to T, into raw_ after room for the uncompressed byte count.
  /// `value` is called from several threads at once for large arrays: it must only read.
  template <class T, class Value>
  void pack(std::size_t count, const Value& value) {
    const Clock::time_point start = Clock::now();
    raw_.resize(kCountBytes + count * sizeof(T));
    std::uint8_t* const to = raw_.data() + kCountBytes;
    const auto values = static_cast<std::ptrdiff_t>(count);
#pragma omp parallel for schedule(static) if (count >= kParallelValues)
    for (std::ptrdiff_t k = 0; k < values; ++k) {
      const T v = static_cast<T>(value(static_cast<std::size_t>(k)));
      std::memcpy(to + static_cast<std::size_t>(k) * sizeof(T), &v, sizeof v);
    }
    seconds_.pack += since(start);
  }
  /// The element around raw_'s values; `size_attribute` is NumberOfComponents for
  /// ordinary arrays and NumberOfTuples for field data, which VTK requires there.
  void emit(OutFile&, std::string_view name, VtkWord word, std::string_view size_attribute,
            int indent);
  /// The array's bytes as VTK stores them, in two parts: [byte count][values] and nothing,
  /// or the compression header and the blocks. Inline, each part is a base64 run; appended
  /// (the element names its offset in the block end_file writes), they wait in appended_.
  std::array<std::span<const std::uint8_t>, 2> binary_parts(const OutFile&);
  /// The compressed array's header_ and blocks, in compressed_ (its first `used` bytes).
  std::size_t compress_raw(const OutFile&);
  void write_ascii(OutFile&, VtkWord word);

  VtkFormat format_;
  std::vector<std::uint8_t> raw_;         ///< [byte count][values] of the array at hand
  std::vector<std::uint8_t> compressed_;  ///< its blocks, compressed, end to end
  std::vector<std::uint64_t> header_;     ///< the compressed array's header
  std::string text_;                      ///< base64 of the above
  std::vector<std::uint8_t> appended_;    ///< the file's appended arrays, end to end
  std::vector<BlockCompressor> compressors_;  ///< one for each OpenMP thread compressing
  Seconds seconds_;
};

}  // namespace tridem::io
