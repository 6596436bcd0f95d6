#pragma once
// Bytes made once and handed to many without a copy: an encoded message to
// every subscriber of a room, a stored package to every request for it.
// Immutable once shared, so that threads read them without a lock.
#include <cstdint>
#include <memory>
#include <vector>

namespace fw::server {

using SharedBytes = std::shared_ptr<const std::vector<std::uint8_t>>;

inline SharedBytes share(std::vector<std::uint8_t>&& bytes) {
  return std::make_shared<const std::vector<std::uint8_t>>(std::move(bytes));
}

}  // namespace fw::server
