#pragma once
// The pieces every VTK XML file we write shares: the root element and data arrays in
// either encoding. Binary arrays are base64 of a UInt64 byte count followed by the raw
// values, encoded as one run, exactly as VTK's own writer does for uncompressed data.
#include "io/output/out_file.hpp"
#include "tridem/output.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string_view>

namespace tridem::io {

/// Opens `<VTKFile type="...">` after the XML declaration, with the host's byte order.
void begin_vtk_file(OutFile&, std::string_view type);
void end_vtk_file(OutFile&);

/// One `<DataArray>`; `values` holds components × tuples numbers. Instantiated for
/// double, std::int64_t, std::int32_t and std::uint8_t.
template <class T>
void write_data_array(OutFile&, std::string_view name, std::span<const T> values,
                      int components, Encoding, int indent);

/// `<FieldData>` with TimeValue (ParaView shows it as the dataset's time) and step.
void write_time_field_data(OutFile&, std::int64_t step, double time, Encoding, int indent);

/// A PolyData file of separate line segments, the contact network's (contacts/*.vtp) and
/// the bonds' (bonds/*.vtp): segment k joins points 2k and 2k + 1 of `points` (x, y, z
/// each), and `cell_data` writes its per-segment arrays inside
/// `<CellData cell_attributes>` (e.g. `Scalars="damage"`), at indent 8.
void write_line_set_vtp(const std::filesystem::path& file, std::int64_t step, double time,
                        std::span<const double> points, std::string_view cell_attributes,
                        Encoding encoding, const std::function<void(OutFile&)>& cell_data);

}  // namespace tridem::io
