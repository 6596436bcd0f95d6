#include "frame_reader.hpp"

#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "frame_writer.hpp"
#include "test_seed.hpp"

namespace fw::codec {
namespace {

// A random decision: any levels, any subset of channels, any values in
// range, any velocities within limits, any damping.
FrameDecision random_decision(std::mt19937_64& rng, FrameType type) {
  FrameDecision d;
  d.type = type;
  d.tick_delta = 1 + static_cast<std::uint32_t>(rng() % (rng() % 8 == 0 ? 65536 : 20));
  d.level = static_cast<int>(rng() % (kMaxQualityLevel + 1));
  const double density = static_cast<double>(rng() % 100) / 100.0;
  for (std::size_t c = 0; c < kChannelCount; ++c) {
    const CodedRange range = coded_range(c);
    d.update[c] = static_cast<double>(rng() % 100) / 100.0 < density;
    d.target[c] = range.min + static_cast<std::int32_t>(rng() % static_cast<std::uint64_t>(range.max - range.min + 1));
    if (rng() % 3 == 0) {
      d.velocity[c] = static_cast<std::int32_t>(rng() % 20001) - 10000;
      if (rng() % 50 == 0) d.velocity[c] = (rng() % 2 ? 1 : -1) * max_velocity(c) * 2;  // beyond the limit: clamped
    }
    d.damping[c] = static_cast<int>(rng() % kDampingClasses);
  }
  return d;
}

TEST(FrameReader, ReadsSeededRandomFramesIntoTheWritersState) {
  const std::uint64_t seed = test::seed("FrameReader.ReadsSeededRandomFrames");
  std::mt19937_64 rng(seed);
  for (int stream = 0; stream < 40; ++stream) {
    const auto limit = static_cast<std::uint8_t>(rng() % 3 == 0 ? rng() % 256 : 32);
    CodingState writer(limit), reader(limit);
    for (int f = 0; f < 60; ++f) {
      const FrameType type = f == 0 || rng() % 15 == 0 ? FrameType::key : FrameType::predicted;
      const FrameDecision d = random_decision(rng, type);
      std::vector<std::uint8_t> out;
      write_frame(writer, {}, 0, d, out);
      ASSERT_LE(out.size(), kMaxFrameBytes);
      std::uint32_t delta = 0;
      ASSERT_EQ(read_frame_payload(reader, type, std::span(out).subspan(1), delta), DecodeError::ok)
          << "stream " << stream << " frame " << f << " seed " << seed;
      ASSERT_EQ(delta, d.tick_delta);
      ASSERT_EQ(reader.level, writer.level);
      for (std::size_t c = 0; c < kChannelCount; ++c) {
        ASSERT_EQ(reader.reconstruction.shown(c), writer.reconstruction.shown(c)) << c << " seed " << seed;
        ASSERT_EQ(reader.reconstruction.velocity(c), writer.reconstruction.velocity(c)) << c << " seed " << seed;
        ASSERT_EQ(reader.reconstruction.damping(c), writer.reconstruction.damping(c)) << c << " seed " << seed;
        ASSERT_LE(std::abs(std::int64_t{writer.reconstruction.velocity(c)}), max_velocity(c));
      }
      // Updated channels land within half a unit of their target.
      for (std::size_t c = 0; c < kChannelCount; ++c) {
        if (type == FrameType::predicted && !d.update[c]) continue;
        const int shift = group_shift(d.level, group_index(channel_table()[c].group));
        ASSERT_LE(std::abs(writer.reconstruction.shown(c) - d.target[c]), (1 << shift) / 2)
            << channel_table()[c].name << " seed " << seed;
      }
    }
  }
}

TEST(FrameReader, ReportsTruncatedAndCorruptPayloadsWithoutReadingOutside) {
  const std::uint64_t seed = test::seed("FrameReader.ReportsCorruptPayloads");
  std::mt19937_64 rng(seed);
  int detected = 0, total = 0;
  for (int i = 0; i < 500; ++i) {
    CodingState writer(32);
    std::vector<std::uint8_t> out;
    write_frame(writer, {}, 0, random_decision(rng, FrameType::key), out);
    std::vector<std::uint8_t> payload(out.begin() + 1, out.end());
    const bool truncate = i % 2 == 0;
    if (truncate) {
      payload.resize(payload.size() - 1 - rng() % payload.size());
    } else {
      payload[rng() % payload.size()] ^= static_cast<std::uint8_t>(1u << (rng() % 8));
    }
    CodingState reader(32);
    std::uint32_t delta = 0;
    // A heap copy of exactly the payload: ASan catches any read past it.
    const auto exact = std::make_unique<std::uint8_t[]>(payload.size() + 1);
    std::copy(payload.begin(), payload.end(), exact.get());
    const DecodeError e = read_frame_payload(reader, FrameType::key, std::span(exact.get(), payload.size()), delta);
    ++total;
    if (e != DecodeError::ok) ++detected;
  }
  // 4 check bits and range checks: far more than 15 in 16 are caught.
  EXPECT_GT(detected, total * 15 / 16) << detected << " of " << total << " seed " << seed;
}

// Cutting the last byte moves the coded value below the final interval: the
// all-ones check bits take its top sixteenth, so nearly every cut lands
// outside them (the rest decode differently earlier and are caught by
// chance or by range checks).
TEST(FrameReader, ATruncatedFrameByOneByteIsNearlyAlwaysCaught) {
  const std::uint64_t seed = test::seed("FrameReader.TruncatedByOneByte");
  std::mt19937_64 rng(seed);
  int caught = 0;
  for (int i = 0; i < 300; ++i) {
    CodingState writer(32);
    std::vector<std::uint8_t> out;
    write_frame(writer, {}, 0, random_decision(rng, FrameType::key), out);
    CodingState reader(32);
    std::uint32_t delta = 0;
    if (read_frame_payload(reader, FrameType::key, std::span(out).subspan(1, out.size() - 2), delta) != DecodeError::ok)
      ++caught;
  }
  EXPECT_GE(caught, 270) << "seed " << seed;
}

}  // namespace
}  // namespace fw::codec
