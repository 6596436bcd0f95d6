#include "fw/behavior/scene_file.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "fw/codec/codec.hpp"

namespace fw::behavior {
namespace {

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("fw_scene_test_" + std::to_string(::getpid()) + "_" + name)).string();
}

Scene small_scene() {
  Scene s;
  s.fps = 25;
  for (int a = 0; a < 2; ++a) {
    SceneAvatar avatar;
    avatar.name = a ? "idle-one" : "talker";
    avatar.idle = a == 1;
    for (int t = 0; t < 10; ++t) {
      codec::FaceParams p;
      for (std::size_t c = 0; c < codec::kChannelCount; ++c)
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
  ASSERT_TRUE(back.avatars[1].seat);  // an unseated avatar gets the default layout's seat
  ASSERT_EQ(back.events.size(), 3u);
  EXPECT_EQ(back.events[2].what, "behavior visual_search -> mimicking (talker)");
  EXPECT_EQ(back.events[2].avatar, 1);
  EXPECT_EQ(back.events[2].tick, 9u);
  std::filesystem::remove(path);
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

}  // namespace
}  // namespace fw::behavior
