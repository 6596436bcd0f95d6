#pragma once
// The CRC-32 that guards each part of an avatar package (FORMAT.md), for
// the writer and the reader alike.
#include <cstdint>
#include <span>

#include <zlib.h>

namespace fw::model {

inline std::uint32_t crc_of(std::span<const std::uint8_t> bytes) {
  return static_cast<std::uint32_t>(crc32(0L, bytes.data(), static_cast<uInt>(bytes.size())));
}

}  // namespace fw::model
