#pragma once
// FaceParams fields <-> grid steps (FORMAT.md, "Channels"), and the rounding
// the coded units use. channel_value(), quantise() and dequantise() are
// declared in codec.hpp.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "fw/codec/codec.hpp"

namespace fw::codec {

/// `value` in grid steps of `channel`, unrounded, clamped to the channel's
/// range; NaN is 0.
double to_steps(float value, std::size_t channel);

/// Nearest multiple of 2^shift, as a count of 2^shift units:
/// floor((q + 2^(shift-1)) / 2^shift), halves rounding up. shift 0 .. 15.
constexpr std::int32_t round_to_units(std::int32_t q, int shift) {
  if (shift == 0) return q;
  const std::int32_t half = std::int32_t{1} << (shift - 1);
  return (q + half) >> shift;  // C++20: >> of a negative number is floor division
}

/// Nearest integer to `x`, halves away from zero (finite |x| < 2^30).
/// Inline: the encoder calls it for every channel of every tick.
inline std::int32_t round_nearest(double x) {
  return static_cast<std::int32_t>(x >= 0 ? std::floor(x + 0.5) : -std::floor(-x + 0.5));
}

/// `q` clamped to the channel's coded range.
std::int32_t clamp_coded(std::int64_t q, std::size_t channel);

}  // namespace fw::codec
