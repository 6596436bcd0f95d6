#pragma once
// The CRC-32 that guards each part of an avatar package (FORMAT.md), for
// the writer and the reader alike: zlib's CRC-32 (reflected polynomial
// 0xEDB88320, initial and final value all ones), written out here rather
// than taken from zlib so that the library needs nothing outside the
// standard library, GLM and JSON: the browser engine compiles these very
// sources to WebAssembly (web/engine), where zlib is not at hand.
#include <array>
#include <cstdint>
#include <span>

namespace fw::model {

namespace detail {
inline constexpr std::array<std::uint32_t, 256> kCrcTable = [] {
  std::array<std::uint32_t, 256> table{};
  for (std::uint32_t n = 0; n < 256; ++n) {
    std::uint32_t c = n;
    for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    table[n] = c;
  }
  return table;
}();
}  // namespace detail

inline std::uint32_t crc_of(std::span<const std::uint8_t> bytes) {
  std::uint32_t c = 0xFFFFFFFFu;
  for (const std::uint8_t b : bytes) c = detail::kCrcTable[(c ^ b) & 0xFFu] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

}  // namespace fw::model
