#pragma once
// The pieces every VTK XML file we write shares: the root element and data arrays in
// either encoding. Binary arrays are base64 of a UInt64 byte count followed by the raw
// values, encoded as one run, exactly as VTK's own writer does for uncompressed data.
#include "io/output/out_file.hpp"
#include "tridem/output.hpp"

#include <cstdint>
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

}  // namespace tridem::io
