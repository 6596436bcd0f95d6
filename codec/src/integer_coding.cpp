#include "integer_coding.hpp"

#include <cassert>

namespace fw::codec {
namespace {

// Magnitude m >= 1 as class k = floor(log2 m) in unary (k ones, then a zero
// unless k is the largest class), then the k bits of m below its leading one.
void encode_magnitude(RangeEncoder& encoder, IntegerModel& model, std::uint32_t m) {
  assert(m >= 1 && m < (1u << kMaxMagnitudeClass));
  int k = 0;
  while ((m >> (k + 1)) != 0) ++k;
  for (int i = 0; i < k; ++i) encoder.encode(model.prefix[static_cast<std::size_t>(i)], 1);
  if (k < kMaxMagnitudeClass - 1) encoder.encode(model.prefix[static_cast<std::size_t>(k)], 0);
  encoder.encode_raw(m & ((1u << k) - 1), k);
}

std::uint32_t decode_magnitude(RangeDecoder& decoder, IntegerModel& model) {
  int k = 0;
  while (k < kMaxMagnitudeClass - 1 && decoder.decode(model.prefix[static_cast<std::size_t>(k)]) == 1) ++k;
  return (1u << k) | decoder.decode_raw(k);
}

}  // namespace

void encode_signed(RangeEncoder& encoder, IntegerModel& model, std::int32_t value) {
  encoder.encode(model.zero, value == 0 ? 0 : 1);
  if (value == 0) return;
  encoder.encode(model.sign, value < 0 ? 1 : 0);
  encode_magnitude(encoder, model, static_cast<std::uint32_t>(value < 0 ? -value : value));
}

std::int32_t decode_signed(RangeDecoder& decoder, IntegerModel& model) {
  if (decoder.decode(model.zero) == 0) return 0;
  const bool negative = decoder.decode(model.sign) == 1;
  const auto m = static_cast<std::int32_t>(decode_magnitude(decoder, model));
  return negative ? -m : m;
}

void encode_unsigned(RangeEncoder& encoder, IntegerModel& model, std::uint32_t value) {
  encoder.encode(model.zero, value == 0 ? 0 : 1);
  if (value != 0) encode_magnitude(encoder, model, value);
}

std::uint32_t decode_unsigned(RangeDecoder& decoder, IntegerModel& model) {
  if (decoder.decode(model.zero) == 0) return 0;
  return decode_magnitude(decoder, model);
}

}  // namespace fw::codec
