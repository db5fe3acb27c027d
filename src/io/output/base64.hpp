#pragma once
// Base64 (RFC 4648, standard alphabet, '=' padding) as VTK XML "binary" inline arrays use it.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tridem::io {

std::string base64_encode(std::span<const std::uint8_t> bytes);
/// Appends the encoding of `bytes` to `out`: a writer that keeps `out` reuses its storage.
void base64_append(std::span<const std::uint8_t> bytes, std::string& out);

/// Skips whitespace. Accepts padding at the end of any 4-character group, not only the
/// last, because some writers encode an array's header and its data as separate runs.
/// Throws Error (naming `what`) on any other character or a truncated group.
std::vector<std::uint8_t> base64_decode(std::string_view text, std::string_view what);

}  // namespace tridem::io
