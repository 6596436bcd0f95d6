#pragma once
// The probability model of one binary decision: the context that the range
// encoder and the range decoder share (FORMAT.md, "Adaptive binary models").
#include <cstdint>

namespace fw::codec {

/// Probabilities are 15-bit fixed point: p0 / 32768 is the chance of a 0.
inline constexpr std::uint32_t kProbabilityBits = 15;
inline constexpr std::uint32_t kProbabilityOne = 1u << kProbabilityBits;
/// p0 stays in [kProbabilityMin, kProbabilityOne - kProbabilityMin], so the
/// unlikely symbol always keeps a codable interval. (The slowest adaptation
/// settles within 64 of certainty, so a likely symbol costs at least
/// log2(32768/32705) = 0.003 bits.)
inline constexpr std::uint32_t kProbabilityMin = 32;

/// An adaptive estimate of P(bit = 0). It learns fast at first and then
/// settles: the adaptation shift grows with the number of bits seen, which
/// approximates a running frequency count (Krichevsky-Trofimov) early and an
/// exponential forgetting window of about 64 bits later.
/// Packed in 3 bytes, not padded to 4: a frame's models are kilobytes of
/// them, held per avatar per viewer on a server, and read from memory.
struct __attribute__((packed)) AdaptiveBit {
  std::uint16_t p0 = kProbabilityOne / 2;
  std::uint8_t seen = 0;  ///< bits seen, saturating at kAdaptationSteps

  /// Moves the estimate toward `bit` (0 or 1).
  void update(int bit);
};

/// Adaptation shift for an AdaptiveBit that has seen `seen` bits.
int adaptation_shift(std::uint8_t seen);
inline constexpr std::uint8_t kAdaptationSteps = 62;

}  // namespace fw::codec
