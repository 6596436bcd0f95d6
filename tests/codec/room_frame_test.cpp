#include "fw/codec/codec.hpp"

#include <vector>

#include <gtest/gtest.h>

namespace fw::codec {
namespace {

TEST(RoomFrame, CarriesAvatarIdsAndFramesWithOneByteOfOverheadForSmallIds) {
  const std::vector<std::uint8_t> a = {0x22, 0x80}, b = {0x21, 1, 2, 3}, c = {0x22};
  const RoomEntry entries[] = {{0, a}, {63, b}, {kMaxAvatarId, c}};
  std::vector<std::uint8_t> out;
  write_room_frame(entries, out);
  EXPECT_EQ(out[0], 0x23);
  EXPECT_EQ(out[1], 0x01) << "avatar 0, more to come";
  EXPECT_EQ(out[2], 2) << "its length";
  std::vector<RoomEntry> back;
  ASSERT_EQ(read_room_frame(out, back), DecodeError::ok);
  ASSERT_EQ(back.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(back[i].avatar_id, entries[i].avatar_id);
    EXPECT_TRUE(std::equal(back[i].frame.begin(), back[i].frame.end(), entries[i].frame.begin(), entries[i].frame.end()));
  }
  std::vector<std::uint8_t> single;
  const RoomEntry one[] = {{5, b}};
  write_room_frame(one, single);
  EXPECT_EQ(single.size(), 2 + b.size()) << "first byte, the avatar, the frame: the last length is implied";
}

TEST(RoomFrame, RefusesMalformedRoomFrames) {
  std::vector<RoomEntry> e;
  EXPECT_EQ(read_room_frame({}, e), DecodeError::empty_frame);
  const std::vector<std::uint8_t> only_header = {0x23};
  EXPECT_EQ(read_room_frame(only_header, e), DecodeError::truncated);
  const std::vector<std::uint8_t> no_frame = {0x23, 0x04};
  EXPECT_EQ(read_room_frame(no_frame, e), DecodeError::empty_frame);
  const std::vector<std::uint8_t> short_entry = {0x23, 0x05, 0x03, 0x21};
  EXPECT_EQ(read_room_frame(short_entry, e), DecodeError::truncated);
  const std::vector<std::uint8_t> twice = {0x23, 0x05, 0x01, 0x21, 0x04, 0x21};
  EXPECT_EQ(read_room_frame(twice, e), DecodeError::duplicate_avatar);
  EXPECT_TRUE(e.empty() || e.size() == 1u);
  const std::vector<std::uint8_t> wrong = {0x22, 0x04, 0x21};
  EXPECT_EQ(read_room_frame(wrong, e), DecodeError::wrong_frame_type);
  std::vector<std::uint8_t> too_big(kMaxRoomFrameBytes + 1, 0x23);
  EXPECT_EQ(read_room_frame(too_big, e), DecodeError::frame_too_large);
  std::vector<std::uint8_t> crowd = {0x23};
  for (std::uint32_t id = 0; id <= kMaxRoomAvatars; ++id) {
    const std::uint32_t head = (id << 1) | 1;  // more to come, every time
    if (head >= 0x80) crowd.push_back(static_cast<std::uint8_t>((head & 0x7F) | 0x80));
    crowd.push_back(static_cast<std::uint8_t>(head >= 0x80 ? head >> 7 : head));
    crowd.insert(crowd.end(), {1, 0x22});
  }
  EXPECT_EQ(read_room_frame(crowd, e), DecodeError::too_many_avatars);
  EXPECT_LE(e.size(), kMaxRoomAvatars);
}

TEST(ResyncRequest, RoundTripsAndRefusesMalformedOnes) {
  const std::uint32_t ids[] = {1, 200, kMaxAvatarId};
  std::vector<std::uint8_t> out;
  write_resync_request(ids, out);
  EXPECT_EQ(out[0], 0x24);
  std::vector<std::uint32_t> back;
  ASSERT_EQ(read_resync_request(out, back), DecodeError::ok);
  EXPECT_EQ(back, std::vector<std::uint32_t>(std::begin(ids), std::end(ids)));
  std::vector<std::uint8_t> none;
  write_resync_request({}, none);
  ASSERT_EQ(read_resync_request(none, back), DecodeError::ok);
  EXPECT_TRUE(back.empty()) << "no ids: the stream's only avatar";
  out.push_back(7);
  EXPECT_EQ(read_resync_request(out, back), DecodeError::trailing_bytes);
  const std::vector<std::uint8_t> big_id = {0x24, 0x01, 0x80, 0x80, 0x80, 0x01};
  EXPECT_EQ(read_resync_request(big_id, back), DecodeError::truncated) << "ids take three bytes at most";
  const std::vector<std::uint8_t> crowd = {0x24, 65};
  EXPECT_EQ(read_resync_request(crowd, back), DecodeError::too_many_avatars);
}

}  // namespace
}  // namespace fw::codec
