#include "fw/codec/codec.hpp"

#include <vector>

#include <gtest/gtest.h>

#include "synthetic_scene.hpp"

namespace fw::codec {
namespace {

TEST(RoomDecoder, DecodesEveryAvatarOfARoomStreamAsItsEncoderReconstructsIt) {
  bench::SyntheticSceneOptions o;
  o.seed = 5;
  o.active_avatars = 3;
  o.idle_avatars = 1;
  o.seconds = 8;
  const auto scene = bench::make_synthetic_scene(o);
  const std::size_t n = scene.avatars.size();
  EncoderOptions e;
  e.target_bps = 800;
  e.container_bytes_per_frame = 2;
  std::vector<Encoder> encoders;
  for (std::size_t a = 0; a < n; ++a) encoders.emplace_back(e);
  RoomDecoder room(e.stream);
  std::vector<std::uint32_t> since(n, 0);
  std::vector<std::vector<std::uint8_t>> frames(n);
  const std::uint32_t ids[] = {7, 0, 1000, 63};  // any ids
  int multi = 0;
  for (std::size_t t = 0; t < scene.tick_count(); ++t) {
    std::vector<RoomEntry> entries;
    for (std::size_t a = 0; a < n; ++a) {
      if (a == 2 && t < 90) continue;  // joins after 3 s
      if (encoders[a].encode(scene.avatars[a].ticks[t], frames[a])) {
        entries.push_back({ids[a], frames[a]});
        since[a] = 0;
      } else {
        ++since[a];
      }
    }
    if (entries.empty()) continue;
    if (entries.size() > 1) ++multi;
    std::vector<std::uint8_t> message;
    write_room_frame(entries, message);
    const auto result = room.decode(message);
    ASSERT_EQ(result.error, DecodeError::ok);
    ASSERT_EQ(result.avatars.size(), entries.size());
    for (const auto& [id, error] : result.avatars) ASSERT_EQ(error, DecodeError::ok) << id;
    for (std::size_t a = 0; a < n; ++a) {
      const Decoder* d = room.avatar(ids[a]);
      if (a == 2 && t < 90) {
        EXPECT_EQ(d, nullptr);
        continue;
      }
      if (!d) continue;
      ASSERT_EQ(d->quantised(since[a]), encoders[a].reconstruction()) << "avatar " << a << " tick " << t;
    }
  }
  EXPECT_GT(multi, 10) << "frames of several avatars shared room frames";
  EXPECT_EQ(room.size(), n);
  EXPECT_TRUE(room.needing_key_frames().empty());
  room.remove(ids[1]);
  EXPECT_EQ(room.avatar(ids[1]), nullptr);
  EXPECT_EQ(room.size(), n - 1);
}

TEST(RoomDecoder, AsksForKeyFramesAndHoldsNoMoreThanARoomOfAvatars) {
  RoomDecoder room;
  const std::vector<std::uint8_t> predicted = {0x22, 0x00};
  for (std::uint32_t id = 0; id < kMaxRoomAvatars + 5; ++id) {
    const RoomEntry entry[] = {{id, predicted}};
    std::vector<std::uint8_t> message;
    write_room_frame(entry, message);
    const auto result = room.decode(message);
    ASSERT_EQ(result.avatars.size(), 1u);
    EXPECT_EQ(result.avatars[0].second,
              id < kMaxRoomAvatars ? DecodeError::awaiting_key_frame : DecodeError::too_many_avatars);
  }
  EXPECT_EQ(room.size(), kMaxRoomAvatars);
  EXPECT_EQ(room.needing_key_frames().size(), kMaxRoomAvatars) << "none has had its key frame";
  const std::vector<std::uint8_t> broken = {0x23};
  EXPECT_EQ(room.decode(broken).error, DecodeError::truncated);
}

}  // namespace
}  // namespace fw::codec
