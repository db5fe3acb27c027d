#pragma once
// Just enough XML to read back the VTK files this project writes: elements, attributes
// and DataArray contents in "ascii" or inline "binary" format or "appended" to the raw
// <AppendedData> block, the binary ones plain or compressed by vtkZLibDataCompressor or
// vtkLZMADataCompressor. It is not a general XML parser (no entities, no base64 appended
// data, no other compressor) and says so when it meets one.
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace tridem::io {

struct XmlDataArray {
  std::string section;  ///< enclosing element: Points, Cells, CellData, FieldData, …
  std::map<std::string, std::string> attributes;
  std::size_t begin = 0, length = 0;  ///< contents between the tags, in VtkXmlFile::source
};

struct VtkXmlFile {
  std::string name;  ///< for messages
  std::string source;
  std::map<std::string, std::string> root;   ///< attributes of <VTKFile>
  std::map<std::string, std::string> piece;  ///< attributes of the first <Piece>
  std::vector<XmlDataArray> arrays;
  /// The raw appended block: its bytes after the underscore, up to its closing tag, in
  /// source; both npos without one.
  std::size_t appended_begin = std::string::npos, appended_end = std::string::npos;
};

/// Parses a file's text; throws Error with `name` in the message on anything malformed.
VtkXmlFile parse_vtk_xml(std::string name, std::string source);

/// The array called `name` inside `section`, or null.
const XmlDataArray* find_array(const VtkXmlFile&, std::string_view section,
                               std::string_view name);

/// Decodes an array's numbers, checking its NumberOfComponents and that it holds exactly
/// `tuples` tuples. Integer types are returned exactly up to 2^53.
std::vector<double> decode_array(const VtkXmlFile&, const XmlDataArray&, int components,
                                 std::size_t tuples);

}  // namespace tridem::io
