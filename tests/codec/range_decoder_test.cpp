#include "range_decoder.hpp"

#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "range_encoder.hpp"
#include "test_seed.hpp"

namespace fw::codec {
namespace {

TEST(RangeDecoder, DecodesSeededRandomStreamsOfAdaptiveAndRawBits) {
  const std::uint64_t seed = test::seed("RangeDecoder.DecodesSeededRandomStreams");
  std::mt19937_64 rng(seed);
  for (int round = 0; round < 300; ++round) {
    // Symbols: (model index or -1 for raw, bit count, value), with skewed models.
    struct Symbol {
      int model;
      int count;
      std::uint32_t value;
    };
    std::vector<Symbol> symbols;
    const int n = static_cast<int>(rng() % 400);
    const double skew = static_cast<double>(rng() % 1000) / 1000.0;
    for (int i = 0; i < n; ++i) {
      if (rng() % 5 == 0) {
        const int count = static_cast<int>(rng() % 25);
        symbols.push_back({-1, count, static_cast<std::uint32_t>(rng()) & ((1u << count) - 1)});
      } else {
        const bool bit = static_cast<double>(rng() % 1000) / 1000.0 < skew;
        symbols.push_back({static_cast<int>(rng() % 4), 1, bit ? 1u : 0u});
      }
    }
    std::array<AdaptiveBit, 4> enc_models{}, dec_models{};
    RangeEncoder enc;
    for (const Symbol& s : symbols) {
      if (s.model < 0) {
        enc.encode_raw(s.value, s.count);
      } else {
        enc.encode(enc_models[static_cast<std::size_t>(s.model)], static_cast<int>(s.value));
      }
    }
    std::vector<std::uint8_t> bytes;
    enc.finish(bytes);
    RangeDecoder dec(bytes);
    for (std::size_t i = 0; i < symbols.size(); ++i) {
      const Symbol& s = symbols[i];
      const std::uint32_t got = s.model < 0 ? dec.decode_raw(s.count)
                                            : static_cast<std::uint32_t>(dec.decode(dec_models[static_cast<std::size_t>(s.model)]));
      ASSERT_EQ(got, s.value) << "round " << round << " symbol " << i << " (seed " << seed << ")";
    }
    EXPECT_EQ(dec.error(), DecodeError::ok);
  }
}

TEST(RangeDecoder, ReadsZerosPastTheEndAndNeverOutside) {
  const std::vector<std::uint8_t> one = {0x5A};
  RangeDecoder dec(std::span<const std::uint8_t>(one.data(), one.size()));
  AdaptiveBit m;
  for (int i = 0; i < 10000; ++i) dec.decode(m);  // far past the end: zeros, no read outside
  EXPECT_EQ(dec.error(), DecodeError::ok);
  RangeDecoder empty({});
  EXPECT_EQ(empty.decode_raw(24), 0u);
}

TEST(RangeDecoder, ACodeStartingOutsideTheIntervalIsCorrupt) {
  const std::vector<std::uint8_t> bytes = {0xFF, 0xFF, 0xFF, 0xFF, 0x12};
  RangeDecoder dec(bytes);
  EXPECT_EQ(dec.error(), DecodeError::check_failed);
  AdaptiveBit m;
  for (int i = 0; i < 100; ++i) dec.decode(m);  // keeps going harmlessly
  dec.fail(DecodeError::value_out_of_range);
  EXPECT_EQ(dec.error(), DecodeError::check_failed) << "the first error stays";
}

}  // namespace
}  // namespace fw::codec
