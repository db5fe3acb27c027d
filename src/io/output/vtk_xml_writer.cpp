#include "io/output/vtk_xml_writer.hpp"

#include "io/output/base64.hpp"

#include <bit>
#include <cstring>
#include <type_traits>
#include <vector>

namespace tridem::io {
namespace {

template <class T>
constexpr std::string_view vtk_type_name() {
  if constexpr (std::is_same_v<T, double>) return "Float64";
  else if constexpr (std::is_same_v<T, std::int64_t>) return "Int64";
  else if constexpr (std::is_same_v<T, std::int32_t>) return "Int32";
  else if constexpr (std::is_same_v<T, std::uint8_t>) return "UInt8";
}

template <class T>
void write_binary(OutFile& out, std::span<const T> values) {
  const std::uint64_t count = values.size_bytes();
  std::vector<std::uint8_t> bytes(sizeof count + values.size_bytes());
  std::memcpy(bytes.data(), &count, sizeof count);
  if (!values.empty()) std::memcpy(bytes.data() + sizeof count, values.data(), count);
  out.write(base64_encode(bytes));
}

template <class T>
void write_ascii(OutFile& out, std::span<const T> values) {
  constexpr std::size_t kPerLine = 6;
  for (std::size_t k = 0; k < values.size(); ++k) {
    if constexpr (std::is_floating_point_v<T>)
      out.print("{:.17g}", values[k]);
    else
      out.print("{}", static_cast<std::int64_t>(values[k]));
    if (k + 1 < values.size()) out.write((k + 1) % kPerLine == 0 ? "\n" : " ");
  }
}

// One element; `size_attribute` is NumberOfComponents for ordinary arrays and
// NumberOfTuples for field data, which VTK requires there.
template <class T>
void emit(OutFile& out, std::string_view name, std::span<const T> values,
          std::string_view size_attribute, Encoding encoding, int indent) {
  const bool binary = encoding == Encoding::Binary;
  out.print("{:{}}<DataArray type=\"{}\"", "", indent, vtk_type_name<T>());
  if (!name.empty()) out.print(" Name=\"{}\"", name);
  out.print(" {} format=\"{}\">\n", size_attribute, binary ? "binary" : "ascii");
  if (binary)
    write_binary(out, values);
  else
    write_ascii(out, values);
  out.print("\n{:{}}</DataArray>\n", "", indent);
}

}  // namespace

void begin_vtk_file(OutFile& out, std::string_view type) {
  const char* order = std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
  out.print("<?xml version=\"1.0\"?>\n"
            "<VTKFile type=\"{}\" version=\"1.0\" byte_order=\"{}\" header_type=\"UInt64\">\n",
            type, order);
}

void end_vtk_file(OutFile& out) { out.write("</VTKFile>\n"); }

template <class T>
void write_data_array(OutFile& out, std::string_view name, std::span<const T> values,
                      int components, Encoding encoding, int indent) {
  emit(out, name, values, fmt::format("NumberOfComponents=\"{}\"", components), encoding,
       indent);
}

template void write_data_array<double>(OutFile&, std::string_view, std::span<const double>,
                                       int, Encoding, int);
template void write_data_array<std::int64_t>(OutFile&, std::string_view,
                                             std::span<const std::int64_t>, int, Encoding, int);
template void write_data_array<std::int32_t>(OutFile&, std::string_view,
                                             std::span<const std::int32_t>, int, Encoding, int);
template void write_data_array<std::uint8_t>(OutFile&, std::string_view,
                                             std::span<const std::uint8_t>, int, Encoding, int);

void write_time_field_data(OutFile& out, std::int64_t step, double time, Encoding encoding,
                           int indent) {
  constexpr std::string_view kOne = "NumberOfTuples=\"1\"";
  out.print("{:{}}<FieldData>\n", "", indent);
  emit(out, "TimeValue", std::span<const double>(&time, 1), kOne, encoding, indent + 2);
  emit(out, "step", std::span<const std::int64_t>(&step, 1), kOne, encoding, indent + 2);
  out.print("{:{}}</FieldData>\n", "", indent);
}

void write_line_set_vtp(const std::filesystem::path& file, std::int64_t step, double time,
                        std::span<const double> points, std::string_view cell_attributes,
                        Encoding encoding, const std::function<void(OutFile&)>& cell_data) {
  const std::size_t m = points.size() / 6;
  std::vector<std::int64_t> connectivity(2 * m), offsets(m);
  for (std::size_t k = 0; k < m; ++k) {
    connectivity[2 * k] = static_cast<std::int64_t>(2 * k);
    connectivity[2 * k + 1] = static_cast<std::int64_t>(2 * k + 1);
    offsets[k] = static_cast<std::int64_t>(2 * (k + 1));
  }
  OutFile out(file);
  begin_vtk_file(out, "PolyData");
  out.write("  <PolyData>\n");
  write_time_field_data(out, step, time, encoding, 4);
  out.print("    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"0\" NumberOfLines=\"{}\" "
            "NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n",
            2 * m, m);
  out.write("      <Points>\n");
  write_data_array<double>(out, "Points", points, 3, encoding, 8);
  out.write("      </Points>\n      <Lines>\n");
  write_data_array<std::int64_t>(out, "connectivity", connectivity, 1, encoding, 8);
  write_data_array<std::int64_t>(out, "offsets", offsets, 1, encoding, 8);
  out.print("      </Lines>\n      <CellData {}>\n", cell_attributes);
  cell_data(out);
  out.write("      </CellData>\n    </Piece>\n  </PolyData>\n");
  end_vtk_file(out);
  out.close();
}

}  // namespace tridem::io
