#include "range_encoder.hpp"

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "range_decoder.hpp"
#include "test_seed.hpp"

namespace fw::codec {
namespace {

TEST(RangeEncoder, AnEmptyCodeTakesNoBytes) {
  RangeEncoder rc;
  std::vector<std::uint8_t> out;
  rc.finish(out);
  EXPECT_TRUE(out.empty()) << "the decoder reads zeros past the end, so nothing needs writing";
}

TEST(RangeEncoder, NeverEndsWithAZeroByte) {
  std::mt19937 rng(static_cast<std::uint32_t>(test::seed("RangeEncoder.NeverEndsWithAZeroByte")));
  for (int round = 0; round < 200; ++round) {
    RangeEncoder rc;
    AdaptiveBit model;
    const int n = static_cast<int>(rng() % 200);
    for (int i = 0; i < n; ++i) rc.encode(model, static_cast<int>(rng() % 2));
    std::vector<std::uint8_t> out;
    rc.finish(out);
    if (!out.empty()) {
      EXPECT_NE(out.back(), 0);
    }
  }
}

TEST(RangeEncoder, CostsCloseToTheEntropy) {
  const std::uint64_t seed = test::seed("RangeEncoder.CostsCloseToTheEntropy");
  std::mt19937_64 rng(seed);
  std::bernoulli_distribution one(0.1);
  RangeEncoder rc;
  AdaptiveBit model;
  const int n = 20000;
  for (int i = 0; i < n; ++i) rc.encode(model, one(rng) ? 1 : 0);
  std::vector<std::uint8_t> out;
  rc.finish(out);
  const double entropy_bytes = n * (-(0.1 * std::log2(0.1) + 0.9 * std::log2(0.9))) / 8;
  // An adaptive estimate with a 64-bit memory pays a few percent over the entropy.
  EXPECT_LT(out.size(), entropy_bytes * 1.08 + 4);
  EXPECT_GT(out.size(), entropy_bytes * 0.95);
}

TEST(RangeEncoder, RawBitsCostOneBitEach) {
  RangeEncoder rc;
  for (int i = 0; i < 100; ++i) rc.encode_raw(0xABCDEF, 24);
  EXPECT_NEAR(static_cast<double>(rc.bits_so_far()), 2400.0, 9.0);
}

}  // namespace
}  // namespace fw::codec
