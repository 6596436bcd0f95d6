// FaceSource: encoders that read one face worked out once a tick write the
// frames encoders given the face itself write, byte for byte, on budgets
// from tight (frames tried, refused and tried again smaller) to loose, with
// held ticks between, and for an encoder that starts mid-stream.
#include "fw/codec/codec.hpp"

#include <vector>

#include <gtest/gtest.h>

#include "synthetic_correctives.hpp"
#include "synthetic_scene.hpp"

namespace fw::codec {
namespace {

const std::vector<FaceParams>& active_face() {
  static const std::vector<FaceParams> ticks = [] {
    bench::SyntheticSceneOptions o;
    o.seed = 11;
    o.active_avatars = 1;
    o.idle_avatars = 0;
    o.seconds = 30;
    bench::Scene scene = bench::make_synthetic_scene(o);
    bench::add_synthetic_correctives(scene, o.seed);
    return scene.avatars.front().ticks;
  }();
  return ticks;
}

EncoderOptions options_at(double bps) {
  EncoderOptions o;
  o.target_bps = bps;
  o.refresh_ticks = 2;
  o.refresh_bucket_share = 1.0;
  o.container_bytes_per_frame = 2.5;
  return o;
}

TEST(FaceSource, EncodersOnASharedSourceWriteTheFramesOfEncodersOnTheFace) {
  const auto& ticks = active_face();
  ASSERT_GT(ticks.size(), 600u);
  const std::vector<double> budgets = {300, 800, 2000, 8000};
  std::vector<Encoder> on_face, on_source;
  for (const double bps : budgets) {
    on_face.emplace_back(options_at(bps));
    on_source.emplace_back(options_at(bps));
  }
  FaceSource source;
  std::vector<std::uint8_t> a, b;
  std::size_t frames = 0, refused_once = 0;
  for (std::size_t t = 0; t < ticks.size(); ++t) {
    source.offer(ticks[t]);
    if (t == 300) {
      // A viewer that joins mid-stream, on each side.
      on_face.emplace_back(options_at(1200));
      on_source.emplace_back(options_at(1200));
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
  EXPECT_GT(frames, 1000u);
  EXPECT_GT(refused_once, 100u) << "the tight budgets refused frames, so trials were taken back";
  EXPECT_EQ(source.ticks(), ticks.size());
}

}  // namespace
}  // namespace fw::codec
