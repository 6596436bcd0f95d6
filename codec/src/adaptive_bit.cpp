#include "adaptive_bit.hpp"

namespace fw::codec {

int adaptation_shift(std::uint8_t seen) {
  // floor(log2(seen + 2)), capped at 6: 1,1,2,2,2,2,3... reaches 6 after 62 bits.
  int shift = 0;
  for (unsigned n = static_cast<unsigned>(seen) + 2; n > 1; n >>= 1) ++shift;
  return shift < 6 ? shift : 6;
}

void AdaptiveBit::update(int bit) {
  const int shift = adaptation_shift(seen);
  std::uint32_t p = p0;
  if (bit == 0) {
    p += (kProbabilityOne - p) >> shift;
  } else {
    p -= p >> shift;
  }
  if (p < kProbabilityMin) p = kProbabilityMin;
  if (p > kProbabilityOne - kProbabilityMin) p = kProbabilityOne - kProbabilityMin;
  p0 = static_cast<std::uint16_t>(p);
  if (seen < kAdaptationSteps) ++seen;
}

}  // namespace fw::codec
