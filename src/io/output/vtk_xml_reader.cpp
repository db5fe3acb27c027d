#include "io/output/vtk_xml_reader.hpp"

#include "io/output/base64.hpp"
#include "io/output/vtk_xml_writer.hpp"
#include "tridem/error.hpp"

#include <fmt/format.h>

#include <bit>
#include <charconv>
#include <cstring>
#include <lzma.h>
#include <span>
#include <zlib.h>

namespace tridem::io {
namespace {

[[noreturn]] void malformed(const VtkXmlFile& f, std::string_view why) {
  throw Error(fmt::format("cannot read '{}' as a VTK XML file: {}", f.name, why));
}

bool is_space(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }

struct Tag {
  std::string name;
  std::map<std::string, std::string> attributes;
  bool closing = false;
  bool self_closing = false;
  std::size_t end = 0;  ///< one past '>'
};

Tag parse_tag(const VtkXmlFile& f, std::size_t at) {
  const std::string& s = f.source;
  const auto name_end = [&](std::size_t p) {
    while (p < s.size() && !is_space(s[p]) && s[p] != '>' && s[p] != '/' && s[p] != '=') ++p;
    return p;
  };
  const auto skip_space = [&](std::size_t p) {
    while (p < s.size() && is_space(s[p])) ++p;
    return p;
  };
  Tag t;
  std::size_t p = at + 1;
  if (p < s.size() && s[p] == '/') {
    t.closing = true;
    ++p;
  }
  std::size_t e = name_end(p);
  t.name = s.substr(p, e - p);
  if (t.name.empty()) malformed(f, fmt::format("a tag without a name at byte {}", at));
  p = e;
  for (;;) {
    p = skip_space(p);
    if (p >= s.size()) malformed(f, fmt::format("unterminated <{}> tag", t.name));
    if (s[p] == '>') {
      t.end = p + 1;
      return t;
    }
    if (s[p] == '/') {
      if (p + 1 >= s.size() || s[p + 1] != '>' || t.closing)
        malformed(f, fmt::format("stray '/' in <{}> tag", t.name));
      t.self_closing = true;
      t.end = p + 2;
      return t;
    }
    e = name_end(p);
    std::string key = s.substr(p, e - p);
    p = skip_space(e);
    if (key.empty() || p >= s.size() || s[p] != '=')
      malformed(f, fmt::format("attribute '{}' of <{}> has no value", key, t.name));
    p = skip_space(p + 1);
    if (p >= s.size() || (s[p] != '"' && s[p] != '\''))
      malformed(f, fmt::format("attribute '{}' of <{}> is not quoted", key, t.name));
    const std::size_t close = s.find(s[p], p + 1);
    if (close == std::string::npos)
      malformed(f, fmt::format("attribute '{}' of <{}> is not closed", key, t.name));
    t.attributes[std::move(key)] = s.substr(p + 1, close - p - 1);
    p = close + 1;
  }
}

std::string attribute(const std::map<std::string, std::string>& attributes,
                      const std::string& key) {
  const auto it = attributes.find(key);
  return it == attributes.end() ? std::string() : it->second;
}

enum class Word { F32, F64, I8, I16, I32, I64, U8, U16, U32, U64 };

struct WordType {
  std::string_view name;
  Word word;
  std::size_t size;
};

constexpr WordType kWordTypes[] = {{"Float32", Word::F32, 4}, {"Float64", Word::F64, 8},
                                   {"Int8", Word::I8, 1},     {"Int16", Word::I16, 2},
                                   {"Int32", Word::I32, 4},   {"Int64", Word::I64, 8},
                                   {"UInt8", Word::U8, 1},    {"UInt16", Word::U16, 2},
                                   {"UInt32", Word::U32, 4},  {"UInt64", Word::U64, 8}};

template <class T>
T load_word(const std::uint8_t* p) {
  T value;
  std::memcpy(&value, p, sizeof value);
  return value;
}

template <class T>
double load(const std::uint8_t* p) {
  T value;
  std::memcpy(&value, p, sizeof value);
  return static_cast<double>(value);
}

double load(Word word, const std::uint8_t* p) {
  switch (word) {
    case Word::F32: return load<float>(p);
    case Word::F64: return load<double>(p);
    case Word::I8: return load<std::int8_t>(p);
    case Word::I16: return load<std::int16_t>(p);
    case Word::I32: return load<std::int32_t>(p);
    case Word::I64: return load<std::int64_t>(p);
    case Word::U8: return load<std::uint8_t>(p);
    case Word::U16: return load<std::uint16_t>(p);
    case Word::U32: return load<std::uint32_t>(p);
    case Word::U64: return load<std::uint64_t>(p);
  }
  return 0;
}

std::vector<double> parse_ascii(const VtkXmlFile& f, std::string_view text,
                                std::string_view label) {
  std::vector<double> values;
  const char* p = text.data();
  const char* const end = p + text.size();
  for (;;) {
    while (p < end && is_space(*p)) ++p;
    if (p == end) return values;
    double value = 0;
    const auto [next, ec] = std::from_chars(p, end, value);
    if (ec != std::errc() || (next < end && !is_space(*next)))
      malformed(f, fmt::format("{} holds '{}', not a number", label,
                               std::string_view(p, std::min<std::size_t>(20, end - p))));
    values.push_back(value);
    p = next;
  }
}

/// One compressed block of `size` bytes at `in` into `want` bytes at `out`: a zlib stream,
/// or with `lzma` an .xz stream (vtkLZMADataCompressor). "" when it holds exactly `want`
/// bytes, else what went wrong.
std::string inflate_block(bool lzma, const std::uint8_t* in, std::size_t size, std::uint8_t* out,
                          std::size_t want) {
  if (lzma) {
    // The decoder takes the dictionary the stream names: ours are 32 KiB, VTK's highest
    // level names 64 MiB; a stream that asks for more than 128 MiB is refused, not
    // allocated for.
    std::uint64_t memory_limit = std::uint64_t{1} << 27;
    std::size_t in_pos = 0, out_pos = 0;
    const lzma_ret rc = lzma_stream_buffer_decode(&memory_limit, 0, nullptr, in, &in_pos, size, out,
                                                  &out_pos, want);
    if (rc != LZMA_OK) return fmt::format("lzma error {}", static_cast<int>(rc));
    if (in_pos != size || out_pos != want)
      return fmt::format("{} of its {} bytes inflate to {} bytes", in_pos, size, out_pos);
    return {};
  }
  uLongf length = static_cast<uLongf>(want);
  const int rc = uncompress(out, &length, in, static_cast<uLong>(size));
  if (rc != Z_OK) return fmt::format("zlib error {}", rc);
  if (length != want) return fmt::format("it inflates to {} bytes", length);
  return {};
}

/// The values of a vtkZLibDataCompressor (or, with `lzma`, vtkLZMADataCompressor) array:
/// `bytes` is its header, [blocks, block size, size of the last block (0: a full one),
/// compressed size of each block], then the blocks.
std::vector<std::uint8_t> inflate_blocks(const VtkXmlFile& f, std::span<const std::uint8_t> bytes,
                                         std::size_t header, std::size_t expected, bool lzma,
                                         std::string_view label) {
  const auto word = [&](std::size_t k) -> std::uint64_t {
    if ((k + 1) * header > bytes.size())
      malformed(f, fmt::format("{}: its compression header is cut short", label));
    return header == 8 ? load_word<std::uint64_t>(bytes.data() + k * header)
                       : load_word<std::uint32_t>(bytes.data() + k * header);
  };
  const std::uint64_t blocks = word(0), block_size = word(1), last = word(2);
  if (blocks > bytes.size() / header)
    malformed(f, fmt::format("{}: its compression header names {} blocks", label, blocks));
  const std::uint64_t total =
      blocks == 0 ? 0 : (blocks - 1) * block_size + (last == 0 ? block_size : last);
  // zlib expands by at most about 1032:1 (an .xz block of 32 KiB by less); a header
  // claiming more is not to be believed (nor allocated for).
  constexpr std::uint64_t kMaxRatio = 1100;
  if (total != expected || (blocks > 0 && (block_size == 0 || last > block_size)) ||
      total > kMaxRatio * (bytes.size() + 1))
    malformed(f, fmt::format("{} holds {} bytes once uncompressed (blocks of {}), expected {}",
                             label, total, block_size, expected));
  std::vector<std::uint8_t> values(expected);
  std::size_t at = (3 + blocks) * header;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::uint64_t size = word(3 + b);
    const std::size_t begin = b * block_size;
    const std::size_t want = b + 1 == blocks ? expected - begin : block_size;
    if (size > bytes.size() - std::min(at, bytes.size()))
      malformed(f, fmt::format("{}: block {} is cut short", label, b));
    const std::string why =
        inflate_block(lzma, bytes.data() + at, size, values.data() + begin, want);
    if (!why.empty())
      malformed(f,
                fmt::format("{}: block {} does not inflate to {} bytes ({})", label, b, want, why));
    at += size;
  }
  if (at != bytes.size())
    malformed(f, fmt::format("{} has {} bytes after its last block", label, bytes.size() - at));
  return values;
}

/// An appended array's bytes in the raw block, from `offset`: its header and values (or
/// compression header and blocks), as far as its header says, checked against the block.
std::span<const std::uint8_t> appended_bytes(const VtkXmlFile& f, std::string_view offset_text,
                                             std::size_t header, bool compressed,
                                             std::string_view label) {
  if (f.appended_begin == std::string::npos)
    malformed(f, fmt::format("{} is appended, but the file has no <AppendedData>", label));
  std::size_t offset = 0;
  const auto [end, ec] =
      std::from_chars(offset_text.data(), offset_text.data() + offset_text.size(), offset);
  if (ec != std::errc() || end != offset_text.data() + offset_text.size())
    malformed(f, fmt::format("{} has offset '{}', not a number", label, offset_text));
  const std::size_t size = f.appended_end - f.appended_begin;
  if (offset > size)
    malformed(f, fmt::format("{}: offset {} is past the appended data", label, offset));
  const auto* block = reinterpret_cast<const std::uint8_t*>(f.source.data() + f.appended_begin);
  const std::span<const std::uint8_t> rest(block + offset, size - offset);
  const auto word = [&](std::size_t k) -> std::uint64_t {
    if ((k + 1) * header > rest.size())
      malformed(f, fmt::format("{}: its header runs past the appended data", label));
    return header == 8 ? load_word<std::uint64_t>(rest.data() + k * header)
                       : load_word<std::uint32_t>(rest.data() + k * header);
  };
  std::uint64_t length = 0;
  if (!compressed) {
    length = header + word(0);
  } else {
    const std::uint64_t blocks = word(0);
    if (blocks > rest.size() / header)
      malformed(f, fmt::format("{}: its compression header names {} blocks", label, blocks));
    length = (3 + blocks) * header;
    for (std::uint64_t b = 0; b < blocks; ++b) length += word(3 + b);
  }
  if (length > rest.size())
    malformed(f, fmt::format("{} runs past the appended data ({} bytes from offset {}, {} there)",
                             label, length, offset, rest.size()));
  return rest.first(static_cast<std::size_t>(length));
}

/// `text` is the element's contents (base64), or for format="appended" its offset.
std::vector<double> parse_binary(const VtkXmlFile& f, std::string_view text, bool appended,
                                 Word word, std::size_t word_size, std::size_t count,
                                 std::string_view label) {
  const char* native = std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
  const std::string order = attribute(f.root, "byte_order");
  if (order != native)
    malformed(f, fmt::format("byte_order '{}' differs from this machine's {}", order, native));
  const std::string header_type = attribute(f.root, "header_type");
  // VTK's default header type, when none is named, is UInt32.
  const std::size_t header = header_type == "UInt64"                          ? 8
                             : header_type == "UInt32" || header_type.empty() ? 4
                                                                              : 0;
  if (header == 0) malformed(f, fmt::format("unsupported header_type '{}'", header_type));
  const std::string compressor = attribute(f.root, "compressor");
  const std::string_view zlib_name = compressor_name(VtkCompression::Zlib);
  const std::string_view lzma_name = compressor_name(VtkCompression::Lzma);
  const bool lzma = compressor == lzma_name;
  if (!compressor.empty() && compressor != zlib_name && !lzma)
    malformed(f, fmt::format("compressor '{}' is not supported (only {} and {})", compressor,
                             zlib_name, lzma_name));

  std::vector<std::uint8_t> bytes;
  if (appended) {
    const auto span = appended_bytes(f, text, header, !compressor.empty(), label);
    bytes.assign(span.begin(), span.end());
  } else {
    bytes = base64_decode(text, fmt::format("cannot read '{}': {}", f.name, label));
  }
  const std::size_t expected = count * word_size;
  std::size_t skip = 0;
  if (!compressor.empty()) {
    bytes = inflate_blocks(f, bytes, header, expected, lzma, label);
  } else {
    if (bytes.size() < header) malformed(f, fmt::format("{} is too short", label));
    const double stated =
        header == 8 ? load<std::uint64_t>(bytes.data()) : load<std::uint32_t>(bytes.data());
    if (stated != static_cast<double>(expected) || bytes.size() - header != expected)
      malformed(f, fmt::format("{} holds {} bytes (header says {}), expected {}", label,
                               bytes.size() - header, stated, expected));
    skip = header;
  }
  std::vector<double> values(count);
  for (std::size_t k = 0; k < count; ++k)
    values[k] = load(word, bytes.data() + skip + k * word_size);
  return values;
}

}  // namespace

VtkXmlFile parse_vtk_xml(std::string name, std::string source) {
  VtkXmlFile f;
  f.name = std::move(name);
  f.source = std::move(source);
  const std::string& s = f.source;
  std::vector<std::string> open;
  bool seen_root = false, seen_piece = false;
  std::size_t p = 0;
  while ((p = s.find('<', p)) != std::string::npos) {
    const auto skip_to = [&](std::string_view terminator) {
      const std::size_t e = s.find(terminator, p);
      if (e == std::string::npos) malformed(f, fmt::format("missing '{}'", terminator));
      p = e + terminator.size();
    };
    if (s.compare(p, 4, "<!--") == 0) {
      skip_to("-->");
      continue;
    }
    if (s.compare(p, 2, "<?") == 0) {
      skip_to("?>");
      continue;
    }
    if (s.compare(p, 2, "<!") == 0) malformed(f, "DOCTYPE and CDATA are not supported");

    Tag t = parse_tag(f, p);
    p = t.end;
    if (t.closing) {
      if (open.empty() || open.back() != t.name)
        malformed(f, fmt::format("</{}> without a matching open tag", t.name));
      open.pop_back();
      continue;
    }
    if (!seen_root) {
      if (t.name != "VTKFile")
        malformed(f, fmt::format("the root element is <{}>, not <VTKFile>", t.name));
      f.root = t.attributes;
      seen_root = true;
    } else if (open.empty()) {
      malformed(f, fmt::format("<{}> after the end of <VTKFile>", t.name));
    }
    if (t.name == "AppendedData") {
      // Raw bytes follow the underscore, '<' among them: the parse of elements ends here,
      // and the file must end with the block's and the root's closing tags.
      if (attribute(t.attributes, "encoding") != "raw")
        malformed(f, fmt::format("appended data in encoding '{}' is not supported (only raw)",
                                 attribute(t.attributes, "encoding")));
      const std::size_t underscore = s.find('_', p);
      if (underscore == std::string::npos || s.find_first_not_of(" \t\r\n", p) != underscore)
        malformed(f, "<AppendedData> does not start with '_'");
      const std::size_t close = s.rfind("</AppendedData>");
      if (close == std::string::npos || close < underscore ||
          s.find_first_not_of(" \t\r\n", close + std::string_view("</AppendedData>").size()) !=
              s.rfind("</VTKFile>") ||
          s.find_first_not_of(" \t\r\n", s.rfind("</VTKFile>") + 10) != std::string::npos)
        malformed(f, "<AppendedData> is not closed at the end of the file");
      f.appended_begin = underscore + 1;
      // VTK puts a newline (and indentation) between the bytes and the closing tag; the
      // arrays' headers say where each ends.
      f.appended_end = close;
      if (open.size() != 1 || open.back() != "VTKFile")
        malformed(f, "<AppendedData> is not directly inside <VTKFile>");
      open.clear();
      break;
    }
    if (t.name == "Piece" && !seen_piece) {
      f.piece = t.attributes;
      seen_piece = true;
    }
    if (t.name == "DataArray") {
      XmlDataArray array{open.empty() ? std::string() : open.back(), std::move(t.attributes), p, 0};
      if (!t.self_closing) {
        const std::size_t e = s.find("</DataArray>", p);
        if (e == std::string::npos) malformed(f, "a <DataArray> is never closed");
        if (s.find('<', p) < e) malformed(f, "an element inside a <DataArray>");
        array.length = e - p;
        p = e + std::string_view("</DataArray>").size();
      }
      f.arrays.push_back(std::move(array));
      continue;
    }
    if (!t.self_closing) open.push_back(t.name);
  }
  if (!seen_root) malformed(f, "no <VTKFile> element");
  if (!open.empty()) malformed(f, fmt::format("<{}> is never closed", open.back()));
  return f;
}

const XmlDataArray* find_array(const VtkXmlFile& f, std::string_view section,
                               std::string_view name) {
  for (const XmlDataArray& a : f.arrays)
    if (a.section == section && attribute(a.attributes, "Name") == name) return &a;
  return nullptr;
}

std::vector<double> decode_array(const VtkXmlFile& f, const XmlDataArray& a, int components,
                                 std::size_t tuples) {
  const std::string label =
      fmt::format("array '{}' in <{}>", attribute(a.attributes, "Name"), a.section);
  const std::string stated_components = attribute(a.attributes, "NumberOfComponents");
  if (!stated_components.empty() || components != 1) {
    int have = 0;
    const auto [end, ec] = std::from_chars(
        stated_components.data(), stated_components.data() + stated_components.size(), have);
    if (ec != std::errc() || end != stated_components.data() + stated_components.size() ||
        have != components)
      malformed(f, fmt::format("{} has NumberOfComponents '{}', expected {}", label,
                               stated_components, components));
  }
  const std::string type = attribute(a.attributes, "type");
  const WordType* word = nullptr;
  for (const WordType& w : kWordTypes)
    if (w.name == type) word = &w;
  if (!word) malformed(f, fmt::format("{} has unsupported type '{}'", label, type));

  const std::size_t count = static_cast<std::size_t>(components) * tuples;
  const std::string_view text = std::string_view(f.source).substr(a.begin, a.length);
  const std::string format = attribute(a.attributes, "format");
  if (format == "binary") return parse_binary(f, text, false, word->word, word->size, count, label);
  if (format == "appended")
    return parse_binary(f, attribute(a.attributes, "offset"), true, word->word, word->size, count,
                        label);
  if (format != "ascii") malformed(f, fmt::format("{} has unsupported format '{}'", label, format));
  std::vector<double> values = parse_ascii(f, text, label);
  if (values.size() != count)
    malformed(f, fmt::format("{} holds {} numbers, expected {}", label, values.size(), count));
  return values;
}

}  // namespace tridem::io
