#pragma once
// Integers over the binary range coder (FORMAT.md, "Integers"): an adaptive
// zero flag, an adaptive sign, then an Elias-gamma magnitude whose unary
// class prefix is adaptive (one model per prefix position) and whose
// mantissa bits are equiprobable. Small values, the common case in
// residuals, cost a bit or two once the models have learned them.
#include <array>
#include <cstdint>

#include "adaptive_bit.hpp"
#include "range_decoder.hpp"
#include "range_encoder.hpp"

namespace fw::codec {

/// Magnitudes are below 2^kMaxMagnitudeClass (so the prefix has at most
/// that many ones and the decoder's loop is bounded).
inline constexpr int kMaxMagnitudeClass = 17;

struct IntegerModel {
  AdaptiveBit zero;
  AdaptiveBit sign;
  std::array<AdaptiveBit, kMaxMagnitudeClass> prefix{};
};

/// @param[in] value  |value| < 2^kMaxMagnitudeClass
void encode_signed(RangeEncoder& encoder, IntegerModel& model, std::int32_t value);
/// The decoder's loop is bounded by kMaxMagnitudeClass whatever the bytes.
std::int32_t decode_signed(RangeDecoder& decoder, IntegerModel& model);

/// @param[in] value  < 2^kMaxMagnitudeClass; the sign model is unused
void encode_unsigned(RangeEncoder& encoder, IntegerModel& model, std::uint32_t value);
std::uint32_t decode_unsigned(RangeDecoder& decoder, IntegerModel& model);

}  // namespace fw::codec
