#include "fw/codec/codec.hpp"

#include <atomic>
#include <cstdlib>
#include <new>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "synthetic_scene.hpp"
#include "test_seed.hpp"

// Counts the bytes this test binary allocates, to check that decoding
// allocates a bounded amount whatever the input. (GCC takes the malloc/free
// pair of a replacement operator new/delete for a mismatch.)
// AddressSanitizer replaces operator new itself, so the count is kept only
// in builds without it (the test says so when it cannot count).
#if defined(__SANITIZE_ADDRESS__)
#define FW_COUNTS_ALLOCATIONS 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define FW_COUNTS_ALLOCATIONS 0
#endif
#endif
#ifndef FW_COUNTS_ALLOCATIONS
#define FW_COUNTS_ALLOCATIONS 1
#endif
namespace {
std::atomic<std::size_t> g_allocated{0};
}  // namespace
#if FW_COUNTS_ALLOCATIONS
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
void* operator new(std::size_t n) {
  g_allocated += n;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#endif

namespace fw::codec {
namespace {

struct Stream {
  std::vector<std::vector<std::uint8_t>> frames;
  std::vector<int> ticks;                      ///< tick of each frame
  std::vector<QuantisedParams> reconstruction;  ///< the encoder's, per tick
};

// `key_every_ticks`: a key frame forced that often as well (0: never).
Stream encode(bool loss_tolerant, int seconds = 10, std::size_t key_every_ticks = 0) {
  bench::SyntheticSceneOptions o;
  o.seed = 11;
  o.active_avatars = 1;
  o.idle_avatars = 0;
  o.seconds = seconds;
  const auto scene = bench::make_synthetic_scene(o);
  EncoderOptions e;
  e.target_bps = 2000;
  e.stream.loss_tolerant = loss_tolerant;
  e.stream.max_extrapolation_ticks = loss_tolerant ? 15 : 32;
  e.max_key_interval_ticks = 60;
  Encoder encoder(e);
  Stream s;
  std::vector<std::uint8_t> frame;
  for (std::size_t t = 0; t < scene.avatars[0].ticks.size(); ++t) {
    if (key_every_ticks > 0 && t > 0 && t % key_every_ticks == 0) encoder.force_key_frame();
    if (encoder.encode(scene.avatars[0].ticks[t], frame)) {
      s.frames.push_back(frame);
      s.ticks.push_back(static_cast<int>(t));
    }
    s.reconstruction.push_back(encoder.reconstruction());
  }
  return s;
}

StreamOptions lossy_options() {
  StreamOptions o;
  o.loss_tolerant = true;
  o.max_extrapolation_ticks = 15;
  return o;
}

TEST(Decoder, ShowsExactlyWhatTheEncoderReconstructsAtEveryTick) {
  const Stream s = encode(false);
  Decoder d;
  std::size_t f = 0;
  int last = 0;
  for (std::size_t t = 0; t < s.reconstruction.size(); ++t) {
    if (f < s.frames.size() && s.ticks[f] == static_cast<int>(t)) {
      ASSERT_EQ(d.decode(s.frames[f++]), DecodeError::ok);
      last = static_cast<int>(t);
      EXPECT_EQ(d.tick(), t + 1) << "ticks counted from before the first";
    }
    ASSERT_EQ(d.quantised(static_cast<std::uint32_t>(static_cast<int>(t) - last)), s.reconstruction[t]) << "tick " << t;
  }
  EXPECT_EQ(d.frames_decoded(), s.frames.size());
  EXPECT_FALSE(d.needs_key_frame());
}

TEST(Decoder, AfterALostFrameShowsAFaceTheEncoderShowedAndRefusesPredictedFramesUntilAKey) {
  const Stream s = encode(true);
  ASSERT_GT(s.frames.size(), 40u);
  const std::uint64_t seed = test::seed("Decoder.AfterALostFrame");
  std::mt19937_64 rng(seed);
  for (int trial = 0; trial < 20; ++trial) {
    const std::size_t lost = 2 + rng() % (s.frames.size() - 10);
    Decoder d(lossy_options());
    int last_good_tick = -1;
    bool gap_seen = false, resynced = false;
    for (std::size_t f = 0; f < s.frames.size(); ++f) {
      if (f == lost) continue;
      const bool key = s.frames[f][0] == 0x21;
      const DecodeError e = d.decode(s.frames[f]);
      if (f == lost + 1 && !key) {
        EXPECT_EQ(e, DecodeError::sequence_gap) << "frame " << f << " seed " << seed;
        gap_seen = true;
        EXPECT_TRUE(d.needs_key_frame());
        // Never a wrong face: frozen at what the encoder showed at the last good frame.
        EXPECT_EQ(d.quantised(), s.reconstruction[static_cast<std::size_t>(last_good_tick)]);
        EXPECT_EQ(d.quantised(30), d.quantised()) << "and it holds still";
      } else if (gap_seen && !resynced && !key) {
        EXPECT_EQ(e, DecodeError::awaiting_key_frame);
        EXPECT_EQ(d.quantised(), s.reconstruction[static_cast<std::size_t>(last_good_tick)]);
      } else {
        ASSERT_EQ(e, DecodeError::ok) << "frame " << f << " seed " << seed;
        if (gap_seen) resynced = true;
        last_good_tick = s.ticks[f];
        EXPECT_EQ(d.quantised(), s.reconstruction[static_cast<std::size_t>(last_good_tick)]);
      }
    }
    bool key_after = false;
    for (std::size_t f = lost + 1; f < s.frames.size(); ++f) key_after = key_after || s.frames[f][0] == 0x21;
    if (key_after) {
      EXPECT_FALSE(d.needs_key_frame()) << "the periodic key frames bring it back, seed " << seed;
    }
  }
}

TEST(Decoder, IgnoresDuplicatesAndLateFramesWithoutLosingItsPlace) {
  const Stream s = encode(true);
  Decoder d(lossy_options());
  ASSERT_EQ(d.decode(s.frames[0]), DecodeError::ok);
  ASSERT_EQ(d.decode(s.frames[1]), DecodeError::ok);
  const QuantisedParams before = d.quantised();
  EXPECT_EQ(d.decode(s.frames[1]), DecodeError::stale_frame);
  EXPECT_EQ(d.decode(s.frames[0]), DecodeError::stale_frame);
  EXPECT_EQ(d.quantised(), before);
  EXPECT_FALSE(d.needs_key_frame());
  EXPECT_EQ(d.decode(s.frames[2]), DecodeError::ok);
}

TEST(Decoder, CorruptAndTruncatedFramesGiveTheirErrorAndFreezeTheFace) {
  const Stream s = encode(false);
  const auto& key = s.frames[0];
  const auto& next = s.frames[1];
  struct Case {
    const char* what;
    std::vector<std::uint8_t> bytes;
    DecodeError expected;
  };
  auto with = [](std::vector<std::uint8_t> v, std::size_t i, std::uint8_t b) {
    v.at(i) = b;
    return v;
  };
  const std::vector<Case> cases = {
      {"empty", {}, DecodeError::empty_frame},
      {"version 0", with(next, 0, 0x02), DecodeError::unsupported_version},
      {"version 15", with(next, 0, 0xF2), DecodeError::unsupported_version},
      {"type 9", with(next, 0, 0x29), DecodeError::unknown_frame_type},
      {"a stream header", with(next, 0, 0x20), DecodeError::wrong_frame_type},
      {"a resync request", with(next, 0, 0x24), DecodeError::wrong_frame_type},
      {"too large", std::vector<std::uint8_t>(kMaxFrameBytes + 1, 0x22), DecodeError::frame_too_large},
      {"a code that starts outside its interval", {0x22, 0xFF, 0xFF, 0xFF, 0xFF}, DecodeError::check_failed},
  };
  for (const Case& c : cases) {
    Decoder d;
    ASSERT_EQ(d.decode(key), DecodeError::ok);
    const QuantisedParams before = d.quantised();
    EXPECT_EQ(d.decode(c.bytes), c.expected) << c.what;
    EXPECT_TRUE(d.needs_key_frame()) << c.what << ": a frame was lost";
    EXPECT_EQ(d.quantised(), before) << c.what;
    EXPECT_EQ(d.decode(next), DecodeError::awaiting_key_frame) << c.what;
    EXPECT_EQ(d.decode(key), DecodeError::ok) << c.what;
  }
  // Truncations: every cut of every one of the first frames is refused.
  int refused = 0, total = 0;
  for (std::size_t f = 0; f < 30; ++f) {
    for (std::size_t keep = 1; keep < s.frames[f].size(); ++keep) {
      Decoder d;
      for (std::size_t g = 0; g < f; ++g) ASSERT_EQ(d.decode(s.frames[g]), DecodeError::ok);
      const std::vector<std::uint8_t> cut(s.frames[f].begin(), s.frames[f].begin() + static_cast<std::ptrdiff_t>(keep));
      const DecodeError e = d.decode(cut);
      ++total;
      if (e != DecodeError::ok) {
        ++refused;
        EXPECT_TRUE(e == DecodeError::check_failed || e == DecodeError::value_out_of_range) << static_cast<int>(e);
      }
    }
  }
  EXPECT_GE(refused, total * 15 / 16) << refused << " of " << total;
}

TEST(Decoder, AFrameRefusedHalfwayLeavesTheFaceAsItWasAndTheNextKeyFrameDecodesAsIfItNeverCame) {
  // A frame is read into the coding state itself: what a refused one read
  // must not show, nor reach the frames after the next key frame.
  const Stream s = encode(false, 20, 45);
  auto is_key = [](const std::vector<std::uint8_t>& frame) {
    return static_cast<FrameType>(frame[0] & 0x0F) == FrameType::key;
  };
  int checked = 0;
  for (std::size_t f = 1; f < s.frames.size(); ++f) {
    if (is_key(s.frames[f])) continue;
    std::size_t key = f + 1;
    while (key < s.frames.size() && !is_key(s.frames[key])) ++key;
    if (key + 5 >= s.frames.size()) break;  // no key frame with frames after it left
    // Cut the frame, and flip one bit of its last byte: both are read
    // partly before the check at its end refuses them.
    std::vector<std::uint8_t> cut(s.frames[f].begin(), s.frames[f].end() - 1);
    std::vector<std::uint8_t> flipped = s.frames[f];
    flipped.back() ^= 0x10;
    for (const auto& bad : {cut, flipped}) {
      Decoder d;
      for (std::size_t g = 0; g < f; ++g) ASSERT_EQ(d.decode(s.frames[g]), DecodeError::ok);
      const QuantisedParams before = d.quantised();
      if (d.decode(bad) == DecodeError::ok) continue;  // the rare change the check lets through
      ++checked;
      EXPECT_EQ(d.quantised(), before) << "frame " << f;
      Decoder reference;
      for (std::size_t g = 0; g < key; ++g) ASSERT_EQ(reference.decode(s.frames[g]), DecodeError::ok);
      for (std::size_t g = key; g < key + 5; ++g) {
        ASSERT_EQ(d.decode(s.frames[g]), DecodeError::ok) << "frame " << g << " after " << f << " was refused";
        ASSERT_EQ(reference.decode(s.frames[g]), DecodeError::ok);
        EXPECT_EQ(d.quantised(), reference.quantised()) << "frame " << g << " after " << f << " was refused";
      }
    }
  }
  EXPECT_GE(checked, 40) << "refused frames checked";
}

TEST(Decoder, AllocatesABoundedAmountWhateverTheBytes) {
  if (!FW_COUNTS_ALLOCATIONS) GTEST_SKIP() << "allocations are not counted under AddressSanitizer";
  const std::uint64_t seed = test::seed("Decoder.AllocatesABoundedAmount");
  std::mt19937_64 rng(seed);
  std::vector<std::uint8_t> big(4 << 20);
  for (auto& b : big) b = static_cast<std::uint8_t>(rng());
  big[0] = 0x22;
  Decoder d;
  std::vector<RoomEntry> entries;
  entries.reserve(kMaxRoomAvatars);
  for (int i = 0; i < 100; ++i) {
    const std::size_t size = rng() % big.size();
    const std::size_t before = g_allocated;
    d.decode(std::span(big).first(size));
    read_room_frame(std::span(big).first(size), entries);
    EXPECT_LE(g_allocated - before, std::size_t{64 * 1024}) << "size " << size << " seed " << seed;
  }
}

}  // namespace
}  // namespace fw::codec
