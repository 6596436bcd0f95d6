#include "fw/codec/codec.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "synthetic_correctives.hpp"
#include "synthetic_scene.hpp"
#include "test_seed.hpp"

namespace fw::codec {
namespace {

FaceParams random_face(std::mt19937_64& rng) {
  FaceParams p;
  for (std::size_t c = 0; c < kChannelCount; ++c) {
    const ChannelInfo& info = channel_table()[c];
    std::uniform_real_distribution<float> d(static_cast<float>(info.min_q) * info.step, static_cast<float>(info.max_q) * info.step);
    set_channel_value(p, c, d(rng));
  }
  return p;
}

const bench::Scene& scene() {
  static const bench::Scene s = [] {
    bench::SyntheticSceneOptions o;
    o.seed = 3;
    o.active_avatars = 2;
    o.idle_avatars = 1;
    o.seconds = 20;
    bench::Scene made = bench::make_synthetic_scene(o);
    bench::add_synthetic_correctives(made, o.seed);
    return made;
  }();
  return s;
}

// How far what a viewer sees strays from the faces of `ticks` at `bps`:
// the largest gaze error (rad) and the RMS error of the action units and of
// the corrective weights.
struct Strays {
  double gaze_max = 0, au_rms = 0, corrective_rms = 0;
};
Strays strays_at(const std::vector<FaceParams>& ticks, double bps) {
  EncoderOptions o;
  o.target_bps = bps;
  Encoder encoder(o);
  std::vector<std::uint8_t> frame;
  Strays s;
  double au_sq = 0, corrective_sq = 0;
  for (const FaceParams& face : ticks) {
    encoder.encode(face, frame);
    const FaceParams shown = dequantise(encoder.reconstruction());
    for (std::size_t c = 0; c < kAuChannelCount; ++c) au_sq += std::pow(shown.au[c] - face.au[c], 2);
    for (std::size_t k = 0; k < kCorrectiveCount; ++k) corrective_sq += std::pow(shown.corrective[k] - face.corrective[k], 2);
    s.gaze_max = std::max(s.gaze_max, static_cast<double>(std::hypot(
                                          shown.eye_left.yaw_rad + shown.head_yaw_rad - face.eye_left.yaw_rad - face.head_yaw_rad,
                                          shown.eye_left.pitch_rad + shown.head_pitch_rad - face.eye_left.pitch_rad - face.head_pitch_rad)));
  }
  const auto n = static_cast<double>(ticks.size());
  s.au_rms = std::sqrt(au_sq / (n * kAuChannelCount));
  s.corrective_rms = std::sqrt(corrective_sq / (n * kCorrectiveCount));
  return s;
}

TEST(Encoder, RoundTripsSeededRandomFacesThroughTheDecoder) {
  const std::uint64_t seed = test::seed("Encoder.RoundTripsSeededRandomFaces");
  std::mt19937_64 rng(seed);
  for (const bool loss_tolerant : {false, true}) {
    EncoderOptions o;
    o.target_bps = 1e7;  // room for everything
    o.min_level = 0;
    o.max_level = 0;
    o.stream.loss_tolerant = loss_tolerant;
    Encoder encoder(o);
    Decoder decoder(o.stream);
    std::vector<std::uint8_t> frame;
    for (int t = 0; t < 300; ++t) {
      const FaceParams face = random_face(rng);
      ASSERT_TRUE(encoder.encode(face, frame)) << "every channel jumped: a frame every tick";
      ASSERT_EQ(decoder.decode(frame), DecodeError::ok) << "tick " << t << " seed " << seed;
      ASSERT_EQ(decoder.quantised(), encoder.reconstruction()) << "tick " << t << " seed " << seed;
      // Level 0 updates every channel that moved by more than a quarter of
      // its visible error, to within half a grid step (the eyes through the
      // head: one step of each).
      const QuantisedParams exact = quantise(face);
      const QuantisedParams shown = decoder.quantised();
      const auto visible = default_visible_error();
      for (std::size_t c = 0; c < kChannelCount; ++c) {
        const double allowed = kLevelFactor[0] * visible[c] / channel_table()[c].step + 2;
        ASSERT_LE(std::abs(shown[c] - exact[c]), allowed) << channel_table()[c].name << " tick " << t << " seed " << seed;
      }
    }
  }
}

TEST(Encoder, SendsAKeyFrameFirstThenPredictedFramesAndKeysOnDemand) {
  EncoderOptions o;
  o.target_bps = 5000;
  Encoder encoder(o);
  std::vector<std::uint8_t> frame;
  const auto& ticks = scene().avatars[0].ticks;
  ASSERT_TRUE(encoder.encode(ticks[0], frame));
  EXPECT_EQ(frame[0], 0x21);
  EXPECT_EQ(encoder.stats().last_type, FrameType::key);
  int predicted = 0;
  for (std::size_t t = 1; t < 60; ++t)
    if (encoder.encode(ticks[t], frame)) {
      EXPECT_EQ(frame[0], 0x22);
      ++predicted;
    }
  EXPECT_GT(predicted, 3);
  encoder.force_key_frame();
  ASSERT_TRUE(encoder.encode(ticks[60], frame)) << "a forced key frame goes out even when nothing changed";
  EXPECT_EQ(frame[0], 0x21);
  EXPECT_EQ(encoder.stats().key_interval_ticks, 0) << "reliable streams send keys on demand only";
}

TEST(Encoder, AStillFaceCostsNothingAfterItsKeyFrameOverAReliableTransport) {
  Encoder encoder({});
  std::vector<std::uint8_t> frame;
  FaceParams face;
  face.set_au(12, 0.4f);
  int frames = 0;
  for (int t = 0; t < 900; ++t) frames += encoder.encode(face, frame) ? 1 : 0;
  EXPECT_EQ(frames, 1);
  EXPECT_EQ(encoder.stats().tick, 899u);
}

TEST(Encoder, RefreshesASlowlyMovingFaceAtLeastEveryRefreshInterval) {
  // A head that turns by half a degree a second (with no extrapolation at
  // the decoder) reaches its tolerance every ten ticks or so: without
  // refreshes it is sent that often, with them whenever it has moved by half
  // a grid step (0.05 degree) once three ticks have passed (every third or
  // fourth tick), each frame bringing the decoder closer; a face that holds
  // still is not refreshed.
  auto run = [](int refresh_ticks, bool drifting, double& worst_error_rad) {
    EncoderOptions options;
    options.refresh_ticks = refresh_ticks;
    options.stream.max_extrapolation_ticks = 0;  // the decoder holds: what it shows is what was sent
    Encoder encoder(options);
    Decoder decoder(options.stream);
    std::vector<std::uint8_t> frame;
    int frames = 0;
    worst_error_rad = 0;
    for (int t = 0; t < 300; ++t) {
      FaceParams face;
      face.head_yaw_rad = drifting ? 0.5f * 3.14159265f / 180.0f * static_cast<float>(t) / 30.0f : 0.0f;
      if (encoder.encode(face, frame)) {
        ++frames;
        EXPECT_EQ(decoder.decode(frame), DecodeError::ok);
      }
      if (t >= 30) worst_error_rad = std::max<double>(worst_error_rad, std::abs(decoder.face().head_yaw_rad - face.head_yaw_rad));
    }
    return frames;
  };
  double error_without = 0, error_with = 0, error_still = 0;
  const int without = run(0, true, error_without);
  const int with = run(3, true, error_with);
  EXPECT_LE(without, 40);
  EXPECT_GE(with, 75);
  EXPECT_LT(error_with, error_without);
  EXPECT_EQ(run(3, false, error_still), 1);  // the key frame only
}

TEST(Encoder, HeldTicksCarryNoFrameButCountInTheFramesTickDelta) {
  // A sender that bundles frames on every third tick holds the other two:
  // frames then come only on the sending ticks, and the decoder's clock
  // (the sum of the frames' tick deltas) stays the sender's.
  Encoder encoder({});
  Decoder decoder;
  std::vector<std::uint8_t> frame;
  std::uint32_t last_sent_tick = 0;
  for (std::uint32_t t = 0; t < 300; ++t) {
    FaceParams face;
    face.head_yaw_rad = 0.3f * std::sin(static_cast<float>(t) / 20.0f);
    if (t % 3 != 0) {
      encoder.hold(face);
      EXPECT_FALSE(encoder.stats().sent);
      continue;
    }
    if (!encoder.encode(face, frame)) continue;
    ASSERT_EQ(decoder.decode(frame), DecodeError::ok);
    last_sent_tick = t;
    EXPECT_EQ(decoder.tick(), t + 1) << "at tick " << t;  // the key frame's delta counts its own tick
  }
  EXPECT_GT(last_sent_tick, 250u);
}

TEST(Encoder, LossTolerantStreamsSendHeartbeatsAndPeriodicKeyFrames) {
  EncoderOptions o;
  o.stream.loss_tolerant = true;
  o.stream.max_extrapolation_ticks = 15;
  o.heartbeat_ticks = 10;
  o.max_key_interval_ticks = 90;
  Encoder encoder(o);
  std::vector<std::uint8_t> frame;
  FaceParams face;
  std::vector<int> sent, keys;
  for (int t = 0; t < 300; ++t) {
    if (encoder.encode(face, frame)) {
      sent.push_back(t);
      if (frame[0] == 0x21) keys.push_back(t);
      EXPECT_EQ(frame[1], static_cast<std::uint8_t>(sent.size() - 1)) << "sequence numbers count frames";
    }
  }
  for (std::size_t i = 1; i < sent.size(); ++i) EXPECT_LE(sent[i] - sent[i - 1], 10);
  ASSERT_GE(keys.size(), 4u);
  for (std::size_t i = 1; i < keys.size(); ++i) EXPECT_LE(keys[i] - keys[i - 1], 90);
}

// The bits sent in every window of `seconds` stay within the budget plus
// the bucket's burst reserve.
void expect_within_budget(const std::vector<double>& bits_per_tick, std::size_t from, std::size_t to, double bps) {
  const double window_s = 10;
  const auto w = static_cast<std::size_t>(window_s * 30);
  for (std::size_t start = from; start + w <= to; start += 30) {
    double sum = 0;
    for (std::size_t t = start; t < start + w; ++t) sum += bits_per_tick[t];
    EXPECT_LE(sum, bps * window_s + 4.5 * bps) << "window at tick " << start << " over " << bps << " bit/s";
  }
}

TEST(Encoder, StaysUnderABudgetThatChangesMidStream) {
  EncoderOptions o;
  o.target_bps = 1200;
  Encoder encoder(o);
  Decoder decoder;
  std::vector<std::uint8_t> frame;
  std::vector<double> bits;
  const auto& ticks = scene().avatars[1].ticks;
  std::uint32_t since = 0;
  for (std::size_t t = 0; t < ticks.size(); ++t) {
    if (t == 300) encoder.set_target_bps(300);
    const bool sent = encoder.encode(ticks[t], frame);
    bits.push_back(sent ? 8.0 * static_cast<double>(frame.size()) : 0.0);
    if (sent) {
      ASSERT_EQ(decoder.decode(frame), DecodeError::ok);
      since = 0;
    } else {
      ++since;
    }
    ASSERT_EQ(decoder.quantised(since), encoder.reconstruction()) << "tick " << t;
  }
  expect_within_budget(bits, 0, 300, 1200);
  expect_within_budget(bits, 300, bits.size(), 300);
  EXPECT_GT(encoder.stats().level, 3) << "a fifth of the budget: coarser";
}

TEST(Encoder, UnderATightBudgetAGazeShiftBringsTheHeadAlong) {
  // A busy face (every action unit moving) keeps the bucket full, so frames
  // are cut down to their most urgent channels. Then the head turns 0.9 rad
  // while the eyes counter-rotate: the eyes are coded as gaze in the world,
  // so a frame that moves them without the head would show them turned
  // away from where they look.
  EncoderOptions o;
  o.target_bps = 300;
  Encoder encoder(o);
  std::vector<std::uint8_t> frame;
  auto busy = [](int t) {
    FaceParams p;
    for (std::size_t c = 0; c < kAuChannelCount; ++c)
      p.au[c] = 0.5f + 0.45f * static_cast<float>(std::sin(0.2 * t + 0.7 * static_cast<double>(c)));
    return p;
  };
  for (int t = 0; t < 150; ++t) encoder.encode(busy(t), frame);
  bool eyes_moved = false;
  for (int t = 150; t < 240 && !eyes_moved; ++t) {
    FaceParams p = busy(t);
    p.head_yaw_rad = 0.9f;
    p.eye_left.yaw_rad = p.eye_right.yaw_rad = -0.3f;
    if (!encoder.encode(p, frame)) continue;
    const FaceParams shown = dequantise(encoder.reconstruction());
    eyes_moved = std::abs(shown.eye_left.yaw_rad + shown.head_yaw_rad - 0.6f) < 0.1f;
    if (std::abs(shown.eye_left.yaw_rad) > 0.01f || std::abs(shown.head_yaw_rad) > 0.01f) {
      EXPECT_NEAR(shown.head_yaw_rad, 0.9f, 0.05f) << "tick " << t << ": the eyes moved without the head";
    }
  }
  EXPECT_TRUE(eyes_moved) << "the gaze shift never went out";
}

TEST(Encoder, KeepsEveryChannelWithinWhatAViewerSeesWhenTheBudgetAllows) {
  EncoderOptions o;
  o.target_bps = 20000;
  o.min_level = o.max_level = 3;
  const auto visible = default_visible_error();
  for (const auto& avatar : scene().avatars) {
    Encoder encoder(o);
    std::vector<std::uint8_t> frame;
    double worst_gaze = 0;
    for (const FaceParams& face : avatar.ticks) {
      encoder.encode(face, frame);
      const FaceParams shown = dequantise(encoder.reconstruction());
      for (std::size_t c = 0; c < kChannelCount; ++c) {
        if (channel_table()[c].group == ChannelGroup::eyes) continue;
        ASSERT_LE(std::abs(channel_value(shown, c) - channel_value(face, c)), visible[c] * 1.001f)
            << channel_table()[c].name << " of " << avatar.name;
      }
      worst_gaze = std::max({worst_gaze,
                             static_cast<double>(std::hypot(shown.eye_left.yaw_rad + shown.head_yaw_rad - face.eye_left.yaw_rad - face.head_yaw_rad,
                                        shown.eye_left.pitch_rad + shown.head_pitch_rad - face.eye_left.pitch_rad - face.head_pitch_rad)),
                             static_cast<double>(std::hypot(shown.eye_right.yaw_rad + shown.head_yaw_rad - face.eye_right.yaw_rad - face.head_yaw_rad,
                                        shown.eye_right.pitch_rad + shown.head_pitch_rad - face.eye_right.pitch_rad - face.head_pitch_rad))});
    }
    EXPECT_LE(worst_gaze, visible[35] * 1.001) << avatar.name;
  }
}

TEST(Encoder, UnderATightBudgetTheCorrectivesGiveWayToGazeAndActionUnits) {
  // The same talking face with and without moving corrective weights, at a
  // budget that keeps the rate control busy: the correctives are coarsened
  // first and sent last, so gaze and action units stay as they were.
  const std::vector<FaceParams>& with = scene().avatars[0].ticks;
  std::vector<FaceParams> without = with;
  for (FaceParams& f : without) f.corrective = {};
  for (const double bps : {250.0, 400.0}) {
    const Strays a = strays_at(with, bps);
    const Strays b = strays_at(without, bps);
    std::printf("%.0f bit/s: gaze max %.4f vs %.4f rad, AU rms %.4f vs %.4f, corrective rms %.4f\n", bps, a.gaze_max,
                b.gaze_max, a.au_rms, b.au_rms, a.corrective_rms);
    EXPECT_LE(a.gaze_max, b.gaze_max * 1.05 + 0.001) << bps << " bit/s";
    EXPECT_LE(a.au_rms, b.au_rms * 1.05 + 0.001) << bps << " bit/s";
    EXPECT_GT(a.corrective_rms, 0.02) << bps << " bit/s: the correctives were coarsened or held";
  }
  // With bits to spare they follow the face within what a viewer sees.
  const double visible = default_visible_error()[kChannelCount - 1];
  EXPECT_LT(strays_at(with, 2000).corrective_rms, visible);
}

TEST(Encoder, NeverWritesAFrameOverTheLimitAndSurvivesNonsenseInput) {
  Encoder encoder({});
  Decoder decoder;
  std::vector<std::uint8_t> frame;
  FaceParams wild;
  for (float& a : wild.au) a = std::numeric_limits<float>::quiet_NaN();
  wild.head_yaw_rad = 1e30f;
  wild.eye_left.yaw_rad = -std::numeric_limits<float>::infinity();
  for (int t = 0; t < 10; ++t)
    if (encoder.encode(wild, frame)) {
      ASSERT_LE(frame.size(), kMaxFrameBytes);
      ASSERT_EQ(decoder.decode(frame), DecodeError::ok);
    }
  EXPECT_EQ(decoder.quantised()[29], 1376);
  EXPECT_EQ(decoder.quantised()[0], 0) << "NaN is the rest pose";
}

EncoderOptions sourced_options(double bps) {
  EncoderOptions o;
  o.target_bps = bps;
  o.refresh_ticks = 2;
  o.refresh_bucket_share = 1.0;
  o.container_bytes_per_frame = 2.5;
  return o;
}

TEST(FaceSource, EncodersOnASharedSourceWriteTheFramesOfEncodersOnTheFace) {
  // Encoders that read one face worked out once a tick (a room's, for all
  // its viewers) write what encoders given the face itself write, byte for
  // byte: budgets from tight (frames tried, refused and tried again
  // smaller) to loose, held ticks between, one encoder starting mid-stream.
  const auto& ticks = scene().avatars[0].ticks;
  ASSERT_GE(ticks.size(), 600u);
  const std::vector<double> budgets = {300, 800, 2000, 8000};
  std::vector<Encoder> on_face, on_source;
  for (const double bps : budgets) {
    on_face.emplace_back(sourced_options(bps));
    on_source.emplace_back(sourced_options(bps));
  }
  FaceSource source;
  std::vector<std::uint8_t> a, b;
  std::size_t frames = 0, refused_once = 0;
  for (std::size_t t = 0; t < ticks.size(); ++t) {
    source.offer(ticks[t]);
    if (t == 300) {
      // A viewer that joins mid-stream, on each side.
      on_face.emplace_back(sourced_options(1200));
      on_source.emplace_back(sourced_options(1200));
    }
    for (std::size_t e = 0; e < on_face.size(); ++e) {
      // Every third tick is held (a bundling or congested stream).
      if (t % 3 == 1) {
        on_face[e].hold(ticks[t]);
        on_source[e].hold(source);
        continue;
      }
      const bool sent_a = on_face[e].encode(ticks[t], a);
      const bool sent_b = on_source[e].encode(source, b);
      ASSERT_EQ(sent_a, sent_b) << "tick " << t << " encoder " << e;
      ASSERT_EQ(a, b) << "tick " << t << " encoder " << e;
      frames += sent_a ? 1 : 0;
      refused_once += !sent_a && on_face[e].stats().bucket_bits > 0 ? 1 : 0;
    }
    for (std::size_t e = 0; e < on_face.size(); ++e)
      ASSERT_EQ(on_face[e].reconstruction(), on_source[e].reconstruction());
  }
  EXPECT_GT(frames, 500u);
  EXPECT_GT(refused_once, 100u) << "the tight budgets refused frames, so trials were taken back";
  EXPECT_EQ(source.ticks(), ticks.size());
}

}  // namespace
}  // namespace fw::codec
