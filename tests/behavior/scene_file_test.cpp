#include "fw/behavior/scene_file.hpp"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include <gtest/gtest.h>

#include "fw/codec/codec.hpp"

namespace fw::behavior {
namespace {

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("fw_scene_test_" + std::to_string(::getpid()) + "_" + name)).string();
}

// Channels of FaceParams schema 1, which scene files of versions 1 and 2 store.
constexpr std::size_t kChannelsBeforeCorrectives = codec::kChannelCount - codec::kCorrectiveCount;

Scene small_scene() {
  Scene s;
  s.fps = 25;
  for (int a = 0; a < 2; ++a) {
    SceneAvatar avatar;
    avatar.name = a ? "idle-one" : "talker";
    avatar.idle = a == 1;
    for (int t = 0; t < 10; ++t) {
      codec::FaceParams p;  // no corrective weights: a scene versions 1 and 2 hold
      for (std::size_t c = 0; c < kChannelsBeforeCorrectives; ++c)
        codec::set_channel_value(p, c, static_cast<float>(t) * 0.01f + static_cast<float>(c) * 0.001f - static_cast<float>(a));
      avatar.ticks.push_back(p);
    }
    s.avatars.push_back(avatar);
  }
  return s;
}

void expect_same_faces(const Scene& a, const Scene& b) {
  ASSERT_EQ(a.avatars.size(), b.avatars.size());
  for (std::size_t i = 0; i < a.avatars.size(); ++i)
    for (std::size_t t = 0; t < a.tick_count(); ++t)
      for (std::size_t c = 0; c < codec::kChannelCount; ++c)
        ASSERT_EQ(codec::channel_value(a.avatars[i].ticks[t], c), codec::channel_value(b.avatars[i].ticks[t], c));
}

char first_bytes_version(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[8] = {};
  in.read(magic, 8);
  return magic[7];
}

TEST(SceneFile, Version1RoundTripsEveryValueBitForBit) {
  const Scene s = small_scene();
  const std::string path = temp_path("round_trip.fwscene");
  std::string error;
  ASSERT_TRUE(write_scene(s, path, error)) << error;
  EXPECT_EQ(first_bytes_version(path), '1');  // nothing version 2 adds: still version 1
  Scene back;
  ASSERT_TRUE(read_scene(path, back, error)) << error;
  EXPECT_EQ(back.name, "fw_scene_test_" + std::to_string(::getpid()) + "_round_trip");
  EXPECT_EQ(back.fps, 25);
  EXPECT_EQ(back.avatars[0].name, "talker");
  EXPECT_TRUE(back.avatars[1].idle);
  EXPECT_FALSE(back.avatars[0].seat);
  expect_same_faces(s, back);
  std::filesystem::remove(path);
}

TEST(SceneFile, Version2CarriesSeatsPresenceAndEvents) {
  Scene s = small_scene();
  s.avatars[1].joined_tick = 3;
  s.avatars[0].seat = Seat{{-120.5f, 0, 30}, 0.4f};
  s.events = {{0, 0, "leads"}, {3, 1, "joins"}, {9, 1, "behavior visual_search -> mimicking (talker)"}};
  const std::string path = temp_path("v2.fws");
  std::string error;
  ASSERT_TRUE(write_scene(s, path, error)) << error;
  EXPECT_EQ(first_bytes_version(path), '2');
  Scene back;
  ASSERT_TRUE(read_scene(path, back, error)) << error;
  expect_same_faces(s, back);
  EXPECT_EQ(back.avatars[1].joined_tick, 3u);
  EXPECT_EQ(back.avatars[1].left_tick, kPresentToTheEnd);
  EXPECT_FALSE(back.avatars[1].present(2));
  EXPECT_TRUE(back.avatars[1].present(3));
  ASSERT_TRUE(back.avatars[0].seat);
  EXPECT_EQ(back.avatars[0].seat->origin_mm.x, -120.5f);
  EXPECT_EQ(back.avatars[0].seat->facing_yaw_rad, 0.4f);
  // An unseated avatar is written where a version 1 scene would have sat it.
  ASSERT_TRUE(back.avatars[1].seat);
  EXPECT_EQ(back.avatars[1].seat->origin_mm, centre_facing_arc_layout(2)[1].origin_mm);
  EXPECT_EQ(back.avatars[1].seat->facing_yaw_rad, centre_facing_arc_layout(2)[1].facing_yaw_rad);
  ASSERT_EQ(back.events.size(), 3u);
  EXPECT_EQ(back.events[2].what, "behavior visual_search -> mimicking (talker)");
  EXPECT_EQ(back.events[2].avatar, 1);
  EXPECT_EQ(back.events[2].tick, 9u);
  std::filesystem::remove(path);
}

// A version 1 file holds no seats: it was recorded when every room sat
// facing the arc's centre, and plays there still, not on today's seats.
TEST(SceneFile, AVersion1SceneSitsOnTheArcItWasRecordedOn) {
  const Scene s = small_scene();
  std::vector<std::uint8_t> bytes;
  std::string error;
  ASSERT_TRUE(write_scene_bytes(s, bytes, error)) << error;
  ASSERT_EQ(bytes[7], '1');
  Scene back;
  ASSERT_TRUE(read_scene_bytes(bytes, back, error)) << error;
  ASSERT_FALSE(back.avatars[0].seat);
  const std::vector<Seat> arc = centre_facing_arc_layout(static_cast<int>(back.avatars.size()));
  for (std::size_t i = 0; i < back.avatars.size(); ++i) {
    EXPECT_EQ(scene_seat(back, i).origin_mm, arc[i].origin_mm);
    EXPECT_EQ(scene_seat(back, i).facing_yaw_rad, arc[i].facing_yaw_rad);
    EXPECT_NE(scene_seat(back, i).facing_yaw_rad, seat_layout(static_cast<int>(back.avatars.size()))[i].facing_yaw_rad);
  }
}

TEST(SceneFile, RefusesFilesThatAreNotScenesOrDoNotAddUp) {
  const std::string path = temp_path("bad.fwscene");
  std::string error;
  ASSERT_TRUE(write_scene(small_scene(), path, error));
  const auto size = std::filesystem::file_size(path);
  std::filesystem::resize_file(path, size - 4);
  Scene back;
  EXPECT_FALSE(read_scene(path, back, error));
  EXPECT_NE(error.find("does not match"), std::string::npos) << error;
  {
    std::ofstream out(path, std::ios::binary);
    out << "[emotion blushing [stage1 duration 100]] and then some more bytes";
  }
  EXPECT_FALSE(read_scene(path, back, error));
  EXPECT_NE(error.find("magic"), std::string::npos) << error;
  EXPECT_FALSE(read_scene(temp_path("missing.fwscene"), back, error));
  Scene empty;
  EXPECT_FALSE(write_scene(empty, path, error));
  Scene bad_event = small_scene();
  bad_event.events = {{99, 0, "after the end"}};
  EXPECT_FALSE(write_scene(bad_event, path, error));
  EXPECT_NE(error.find("event"), std::string::npos) << error;
  std::filesystem::remove(path);
}

TEST(SceneFile, Version2EventsCutShortAreRefused) {
  Scene s = small_scene();
  s.events = {{1, 0, "chat (joy)"}};
  const std::string path = temp_path("cut.fws");
  std::string error;
  ASSERT_TRUE(write_scene(s, path, error));
  std::filesystem::resize_file(path, std::filesystem::file_size(path) - 3);
  Scene back;
  EXPECT_FALSE(read_scene(path, back, error));
  EXPECT_NE(error.find("cut short"), std::string::npos) << error;
  std::filesystem::remove(path);
}

// ---- Corrupt, truncated and oversized input: every one refused with what
// was wrong and where, whatever the bytes.

std::vector<std::uint8_t> bytes_of(const Scene& s) {
  std::vector<std::uint8_t> bytes;
  std::string error;
  EXPECT_TRUE(write_scene_bytes(s, bytes, error)) << error;
  return bytes;
}

// small_scene() with everything version 2 adds: presence, a seat, events.
Scene small_v2_scene() {
  Scene s = small_scene();
  s.avatars[1].joined_tick = 3;
  s.avatars[0].seat = Seat{{-120.5f, 0, 30}, 0.4f};
  s.events = {{0, 0, "leads"}, {3, 1, "joins"}, {9, 1, "chat (joy)"}};
  return s;
}

// Where the parts of small_v2_scene()'s file start (codec/FORMAT.md, appendix A).
constexpr std::size_t kTicksAt = 16;
constexpr std::size_t kEventsAt = 20;
constexpr std::size_t kFirstAvatarAt = 24;
constexpr std::size_t kAvatarBytes = 2 + 6 + 8 + 16;  // "talker"
constexpr std::size_t kFacesAt = kFirstAvatarAt + kAvatarBytes + (2 + 8 + 8 + 16);  // then "idle-one"
constexpr std::size_t kEventsListAt = kFacesAt + 10 * 2 * kChannelsBeforeCorrectives * 4;

void put_u32(std::vector<std::uint8_t>& bytes, std::size_t at, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) bytes[at + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(value >> (8 * i));
}

// The error read_scene_bytes gives for `bytes`; fails the test if it reads them.
std::string refusal(const std::vector<std::uint8_t>& bytes) {
  Scene scene;
  std::string error;
  EXPECT_FALSE(read_scene_bytes(bytes, scene, error)) << "read " << bytes.size() << " corrupt bytes";
  EXPECT_FALSE(error.empty());
  return error;
}

#define EXPECT_SAYS(error, text) EXPECT_NE((error).find(text), std::string::npos) << "error: " << (error)

TEST(SceneFile, BytesRoundTripInMemory) {
  for (const Scene& s : {small_scene(), small_v2_scene()}) {
    Scene back;
    std::string error;
    ASSERT_TRUE(read_scene_bytes(bytes_of(s), back, error)) << error;
    expect_same_faces(s, back);
    EXPECT_EQ(back.events.size(), s.events.size());
    EXPECT_EQ(back.fps, s.fps);
  }
}

TEST(SceneFile, EveryTruncationIsRefusedAndSaysWhere) {
  const std::vector<std::uint8_t> whole = bytes_of(small_v2_scene());
  ASSERT_EQ(whole.size(), kEventsListAt + 3 * 7 + 5 + 5 + 10);
  for (std::size_t size = 0; size < whole.size(); ++size) {
    const std::string error = refusal({whole.begin(), whole.begin() + static_cast<std::ptrdiff_t>(size)});
    EXPECT_SAYS(error, "byte");  // even the magic: "at byte 0"
  }
  EXPECT_SAYS(refusal({whole.begin(), whole.begin() + 20}), "the header is cut short");
  EXPECT_SAYS(refusal({whole.begin(), whole.begin() + kFirstAvatarAt + 5}), "avatar 0's name is cut short");
  EXPECT_SAYS(refusal({whole.begin(), whole.begin() + kFirstAvatarAt + 10}), "avatar 0's presence and seat");
  EXPECT_SAYS(refusal({whole.begin(), whole.begin() + kFacesAt + 100}), "size does not match 10 ticks of 2 avatars");
  EXPECT_SAYS(refusal({whole.begin(), whole.begin() + kEventsListAt + 9}), "event list is cut short");
  EXPECT_SAYS(refusal({whole.end() - 4, whole.end()}), "magic");
}

TEST(SceneFile, HugeCountsAreRefusedBeforeAnythingIsAllocated) {
  const std::vector<std::uint8_t> whole = bytes_of(small_v2_scene());
  auto with_u32 = [&](std::size_t at, std::uint32_t value) {
    std::vector<std::uint8_t> bytes = whole;
    put_u32(bytes, at, value);
    return refusal(bytes);
  };
  EXPECT_SAYS(with_u32(kTicksAt, 0xFFFFFFFFu), "the header says 4294967295 ticks (byte 16); a scene has 1 to 108000");
  EXPECT_SAYS(with_u32(kTicksAt, 0), "0 ticks");
  // Within the limits, but more than the file holds.
  EXPECT_SAYS(with_u32(kTicksAt, kMaxSceneTicks), "size does not match 108000 ticks of 2 avatars");
  EXPECT_SAYS(with_u32(kEventsAt, 0xFFFFFFFFu), "4294967295 events");
  EXPECT_SAYS(with_u32(kEventsAt, kMaxSceneEvents), "1000000 events take at least 7000000 bytes");
  std::vector<std::uint8_t> avatars = whole;
  avatars[14] = 0xFF;
  avatars[15] = 0xFF;
  EXPECT_SAYS(refusal(avatars), "65535 avatars (byte 14)");
  std::vector<std::uint8_t> fps = whole;
  fps[12] = 0;
  fps[13] = 0;
  EXPECT_SAYS(refusal(fps), "0 ticks per second");
  std::vector<std::uint8_t> name = whole;
  name[kFirstAvatarAt + 1] = 200;
  EXPECT_SAYS(refusal(name), "avatar 0 has a name of 200 bytes (byte 25); at most 64");
  std::vector<std::uint8_t> text = whole;
  text[text.size() - 10 - 1] = 255;  // the last event's text length, past the end
  EXPECT_SAYS(refusal(text), "event 2's text is cut short");
}

TEST(SceneFile, WrongMagicVersionOrSchemaIsRefused) {
  std::vector<std::uint8_t> bytes = bytes_of(small_scene());
  bytes[7] = '4';
  EXPECT_SAYS(refusal(bytes), "version '4'");
  bytes[7] = 0;
  EXPECT_SAYS(refusal(bytes), "version 0x00");
  bytes[0] = 'X';
  EXPECT_SAYS(refusal(bytes), "no FWSCENE1, FWSCENE2 or FWSCENE3 magic");
  EXPECT_SAYS(refusal({}), "magic");
  EXPECT_SAYS(refusal({'F', 'W', 'S'}), "magic");
  std::vector<std::uint8_t> schema = bytes_of(small_scene());
  schema[8] = 2;
  EXPECT_SAYS(refusal(schema), "schema 2");
}

// small_scene() with corrective weights that move.
Scene scene_with_correctives() {
  Scene s = small_scene();
  for (SceneAvatar& a : s.avatars)
    for (std::size_t t = 0; t < a.ticks.size(); ++t)
      for (std::size_t k = 0; k < codec::kCorrectiveCount; ++k)
        a.ticks[t].corrective[k] = 0.05f * static_cast<float>(t) - 0.1f * static_cast<float>(k);
  return s;
}

TEST(SceneFile, Version3CarriesTheCorrectiveWeights) {
  const Scene s = scene_with_correctives();
  const std::vector<std::uint8_t> bytes = bytes_of(s);
  EXPECT_EQ(bytes[7], '3');
  EXPECT_EQ(bytes[8], codec::kFaceParamsSchema) << "schema 2";
  EXPECT_EQ(bytes[10], codec::kChannelCount) << "53 channels";
  Scene back;
  std::string error;
  ASSERT_TRUE(read_scene_bytes(bytes, back, error)) << error;
  expect_same_faces(s, back);
  EXPECT_TRUE(back.avatars[0].seat) << "version 3 seats every avatar, as version 2 does";
  std::vector<std::uint8_t> again;
  ASSERT_TRUE(write_scene_bytes(back, again, error)) << error;
  EXPECT_EQ(again, bytes) << "one file per scene";
}

TEST(SceneFile, OlderVersionsStillReadWithTheirCorrectivesAtZero) {
  for (const Scene& old : {small_scene(), small_v2_scene()}) {
    const std::vector<std::uint8_t> bytes = bytes_of(old);
    ASSERT_NE(bytes[7], '3');
    EXPECT_EQ(bytes[8], 1) << "schema 1";
    EXPECT_EQ(bytes[10], kChannelsBeforeCorrectives);
    Scene back;
    std::string error;
    ASSERT_TRUE(read_scene_bytes(bytes, back, error)) << error;
    for (const SceneAvatar& a : back.avatars)
      for (const codec::FaceParams& face : a.ticks)
        for (const float w : face.corrective) ASSERT_EQ(w, 0.0f);
    expect_same_faces(old, back);
  }
}

TEST(SceneFile, AVersion3FileWithoutCorrectivesOrWithTheOldTableIsRefused) {
  // A scene without correctives is written as version 2; a version 3 file
  // claiming none is not one the writer makes.
  std::vector<std::uint8_t> zeroed = bytes_of(scene_with_correctives());
  const std::size_t faces_at = zeroed.size() - 10 * 2 * codec::kChannelCount * 4;
  for (std::size_t f = 0; f < 10 * 2; ++f)
    for (std::size_t b = kChannelsBeforeCorrectives * 4; b < codec::kChannelCount * 4; ++b)
      zeroed[faces_at + f * codec::kChannelCount * 4 + b] = 0;
  EXPECT_SAYS(refusal(zeroed), "corrective weights are all 0");
  std::vector<std::uint8_t> old_table = bytes_of(scene_with_correctives());
  old_table[8] = 1;
  EXPECT_SAYS(refusal(old_table), "version 3 scenes of schema 2 with 53");
}

TEST(SceneFile, TrailingGarbageIsRefused) {
  std::vector<std::uint8_t> v1 = bytes_of(small_scene());
  v1.push_back(0);
  EXPECT_SAYS(refusal(v1), "a version 1 file ends with its faces");
  std::vector<std::uint8_t> v2 = bytes_of(small_v2_scene());
  const std::size_t end = v2.size();
  v2.insert(v2.end(), {'j', 'u', 'n', 'k'});
  EXPECT_SAYS(refusal(v2), "4 bytes follow the last event, from byte " + std::to_string(end));
}

TEST(SceneFile, CorruptValuesAreRefusedWithWhatAndWhere) {
  const std::vector<std::uint8_t> whole = bytes_of(small_v2_scene());
  auto with_u32 = [&](std::size_t at, std::uint32_t value) {
    std::vector<std::uint8_t> bytes = whole;
    put_u32(bytes, at, value);
    return refusal(bytes);
  };
  const std::uint32_t nan_bits = 0x7FC00000u;
  EXPECT_SAYS(with_u32(kFacesAt + 4 * 3, nan_bits), "avatar 0 at tick 0: channel 3 holds nan (byte " +
                                                        std::to_string(kFacesAt + 12) + ")");
  EXPECT_SAYS(with_u32(kFirstAvatarAt + 2 + 6 + 8, 0x7F800000u), "avatar 0's seat holds inf");
  // Presence: joins after the end, leaves before it joined.
  EXPECT_SAYS(with_u32(kFirstAvatarAt + 2 + 6, 10), "avatar 0 joins at tick 10");
  EXPECT_SAYS(with_u32(kFirstAvatarAt + kAvatarBytes + 2 + 8 + 4, 2), "avatar 1 joins at tick 3 and leaves at tick 2");
  std::vector<std::uint8_t> flags = whole;
  flags[kFirstAvatarAt] = 0x80;
  EXPECT_SAYS(refusal(flags), "avatar 0 has flags 128 (byte 24)");
  // Events: an avatar or tick the scene does not have, or out of order.
  std::vector<std::uint8_t> avatar = whole;
  avatar[kEventsListAt + 4] = 2;
  EXPECT_SAYS(refusal(avatar), "event 0 (byte " + std::to_string(kEventsListAt) + ") names avatar 2");
  EXPECT_SAYS(with_u32(kEventsListAt, 10), "event 0 (byte " + std::to_string(kEventsListAt) + ") happens at tick 10");
  EXPECT_SAYS(with_u32(kEventsListAt + 24, 2), "event 2 (byte " + std::to_string(kEventsListAt + 24) +
                                                 ") at tick 2 follows one at tick 3; events go in tick order");
}

TEST(SceneFile, FileErrorsNameTheFile) {
  const std::string path = temp_path("corrupt.fws");
  std::vector<std::uint8_t> bytes = bytes_of(small_v2_scene());
  bytes.resize(bytes.size() - 1);
  {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  }
  Scene back;
  std::string error;
  EXPECT_FALSE(read_scene(path, back, error));
  EXPECT_EQ(error.rfind(path + ": event 2's text is cut short", 0), 0u) << error;
  // Larger than any scene the limits allow (sparse: no disk is used): refused unread.
  std::filesystem::resize_file(path, 2'000'000'000);
  EXPECT_FALSE(read_scene(path, back, error));
  EXPECT_SAYS(error, "more than the largest scene");
  std::filesystem::remove(path);
}

TEST(SceneFile, WriterRefusesWhatTheReaderWould) {
  std::vector<std::uint8_t> bytes;
  std::string error;
  Scene nan = small_scene();
  codec::set_channel_value(nan.avatars[0].ticks[4], 7, std::numeric_limits<float>::quiet_NaN());
  EXPECT_FALSE(write_scene_bytes(nan, bytes, error));
  EXPECT_SAYS(error, "finite");
  Scene left_early = small_v2_scene();
  left_early.avatars[1].left_tick = 2;
  EXPECT_FALSE(write_scene_bytes(left_early, bytes, error));
  EXPECT_SAYS(error, "joins at tick 3 and leaves at tick 2");
  EXPECT_TRUE(bytes.empty()) << "nothing written";
}

}  // namespace
}  // namespace fw::behavior
