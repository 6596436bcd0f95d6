#include "integer_coding.hpp"

#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "test_seed.hpp"

namespace fw::codec {
namespace {

TEST(IntegerCoding, RoundTripsSignedAndUnsignedValuesOfEveryMagnitude) {
  const std::uint64_t seed = test::seed("IntegerCoding.RoundTrips");
  std::mt19937_64 rng(seed);
  std::vector<std::int32_t> values = {0, 1, -1, 2, -2, 3, (1 << 16) - 1, -((1 << 17) - 1), (1 << 17) - 1};
  for (int i = 0; i < 2000; ++i) {
    const int bits = static_cast<int>(rng() % 17);
    const auto m = static_cast<std::int32_t>(rng() & ((1u << bits) - 1));
    values.push_back(rng() % 2 ? m : -m);
  }
  RangeEncoder enc;
  IntegerModel es, eu;
  for (const std::int32_t v : values) {
    encode_signed(enc, es, v);
    encode_unsigned(enc, eu, static_cast<std::uint32_t>(v < 0 ? -v : v));
  }
  std::vector<std::uint8_t> bytes;
  enc.finish(bytes);
  RangeDecoder dec(bytes);
  IntegerModel ds, du;
  for (const std::int32_t v : values) {
    ASSERT_EQ(decode_signed(dec, ds), v) << "seed " << seed;
    ASSERT_EQ(decode_unsigned(dec, du), static_cast<std::uint32_t>(v < 0 ? -v : v)) << "seed " << seed;
  }
}

TEST(IntegerCoding, SmallValuesBecomeCheapOnceLearned) {
  RangeEncoder enc;
  IntegerModel m;
  for (int i = 0; i < 1000; ++i) encode_signed(enc, m, i % 2 ? 1 : -1);
  EXPECT_LT(enc.bits_so_far(), 1000u * 5 / 2) << "zero flag and prefix learned: about the sign bit each";
}

TEST(IntegerCoding, DecodingGarbageStaysBounded) {
  const std::vector<std::uint8_t> ones(64, 0xFF);
  RangeDecoder dec(std::span<const std::uint8_t>(ones.data() + 1, ones.size() - 1));
  IntegerModel m;
  for (int i = 0; i < 100; ++i) {
    const std::int32_t v = decode_signed(dec, m);
    ASSERT_LT(v < 0 ? -static_cast<std::int64_t>(v) : v, std::int64_t{1} << kMaxMagnitudeClass);
  }
}

}  // namespace
}  // namespace fw::codec
