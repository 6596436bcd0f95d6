#pragma once
// The layout of tcp_framing_fuzz's input, shared with fuzz_make_seeds: one
// byte whose low bit picks the limit (0: a server reading a client, 1: a
// client reading a server), four bytes giving the sizes of the pieces the
// stream arrives in (n + 1 bytes, 255: all the rest at once), then the
// stream.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "fw/codec/messages.hpp"

namespace fw::fuzz {

struct TcpFramingInput {
  static constexpr std::size_t kHeaderBytes = 5;
  static constexpr std::uint8_t kAllAtOnce = 255;

  std::size_t limit = codec::kMaxUpstreamMessageBytes;
  std::array<std::size_t, 4> piece_bytes{};
  std::span<const std::uint8_t> stream;

  static std::optional<TcpFramingInput> parse(std::span<const std::uint8_t> bytes) {
    if (bytes.size() < kHeaderBytes) return std::nullopt;
    TcpFramingInput input;
    input.limit = (bytes[0] & 1) ? codec::kMaxDownstreamMessageBytes : codec::kMaxUpstreamMessageBytes;
    for (std::size_t i = 0; i < 4; ++i)
      input.piece_bytes[i] = bytes[1 + i] == kAllAtOnce ? bytes.size() : std::size_t{bytes[1 + i]} + 1;
    input.stream = bytes.subspan(kHeaderBytes);
    return input;
  }

  /// `pieces`: the bytes of the header's four piece sizes, as above.
  static std::vector<std::uint8_t> make(bool downstream, std::array<std::uint8_t, 4> pieces,
                                        std::span<const std::uint8_t> stream) {
    std::vector<std::uint8_t> bytes(kHeaderBytes + stream.size());
    bytes[0] = downstream ? 1 : 0;
    std::copy(pieces.begin(), pieces.end(), bytes.begin() + 1);
    std::copy(stream.begin(), stream.end(), bytes.begin() + kHeaderBytes);
    return bytes;
  }
};

}  // namespace fw::fuzz
