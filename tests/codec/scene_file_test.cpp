#include "scene_file.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "fw/codec/codec.hpp"

namespace fw::bench {
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

TEST(SceneFile, RoundTripsEveryValueBitForBit) {
  const Scene s = small_scene();
  const std::string path = temp_path("round_trip.fwscene");
  std::string error;
  ASSERT_TRUE(write_scene(s, path, error)) << error;
  Scene back;
  ASSERT_TRUE(read_scene(path, back, error)) << error;
  EXPECT_EQ(back.name, "fw_scene_test_" + std::to_string(::getpid()) + "_round_trip");
  EXPECT_EQ(back.fps, 25);
  ASSERT_EQ(back.avatars.size(), 2u);
  EXPECT_EQ(back.avatars[0].name, "talker");
  EXPECT_TRUE(back.avatars[1].idle);
  for (std::size_t a = 0; a < 2; ++a)
    for (std::size_t t = 0; t < 10; ++t)
      for (std::size_t c = 0; c < codec::kChannelCount; ++c)
        ASSERT_EQ(codec::channel_value(back.avatars[a].ticks[t], c), codec::channel_value(s.avatars[a].ticks[t], c));
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
    out << "FWSCENE2 and then some more bytes";
  }
  EXPECT_FALSE(read_scene(path, back, error));
  EXPECT_NE(error.find("magic"), std::string::npos) << error;
  EXPECT_FALSE(read_scene(temp_path("missing.fwscene"), back, error));
  Scene empty;
  EXPECT_FALSE(write_scene(empty, path, error));
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace fw::bench
