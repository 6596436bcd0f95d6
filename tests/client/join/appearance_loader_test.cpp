#include "appearance_loader.hpp"

#include <sstream>

#include <gtest/gtest.h>

namespace fw::client {
namespace {

using Bytes = std::vector<std::uint8_t>;

void give_package(RoomState& state, std::uint32_t avatar, Bytes bytes) {
  std::lock_guard lock(state.mutex);
  RoomAvatar& entry = state.avatars[avatar];
  entry.package = std::make_shared<const Bytes>(std::move(bytes));
  ++entry.package_serial;
}

TEST(AppearanceLoader, TakesEachNewPackageOnce) {
  RoomState state;
  std::ostringstream log;
  AppearanceLoader loader(log);
  state.avatars[1];  // no package yet
  give_package(state, 2, {1});
  give_package(state, 3, {2});
  auto fresh = loader.take_new(state).packages;
  ASSERT_EQ(fresh.size(), 2u);
  EXPECT_EQ(fresh[0].first, 2u);
  EXPECT_EQ(*fresh[1].second, Bytes{2});
  EXPECT_TRUE(loader.take_new(state).packages.empty()) << "nothing new";
  give_package(state, 2, {3});  // the full package after the preview
  fresh = loader.take_new(state).packages;
  ASSERT_EQ(fresh.size(), 1u);
  EXPECT_EQ(*fresh[0].second, Bytes{3});
}

codec::UnitMorphs units(std::uint32_t avatar, std::uint32_t version) {
  codec::UnitMorphs message;
  message.avatar = avatar;
  message.version = version;
  return message;
}

TEST(AppearanceLoader, TakesEachNewVersionOfUnitsOnceAndLetsGoOfThoseWhoLeft) {
  RoomState state;
  std::ostringstream log;
  AppearanceLoader loader(log);
  give_package(state, 2, {1});
  state.unit_morphs_arrived(units(2, 1));
  state.unit_morphs_arrived(units(5, 1));  // before its package and presence
  auto changes = loader.take_new(state);
  ASSERT_EQ(changes.units.size(), 2u);
  EXPECT_EQ(changes.units[0].avatar, 2u);
  EXPECT_TRUE(changes.gone.empty());
  EXPECT_TRUE(loader.take_new(state).units.empty()) << "nothing new";
  EXPECT_FALSE(state.unit_morphs_arrived(units(2, 1))) << "not newer";
  EXPECT_TRUE(state.unit_morphs_arrived(units(2, 2)));
  changes = loader.take_new(state);
  ASSERT_EQ(changes.units.size(), 1u);
  EXPECT_EQ(changes.units[0].version, 2u);
  state.avatar_left(2);
  EXPECT_FALSE(state.unit_morphs.contains(2));
  changes = loader.take_new(state);
  EXPECT_EQ(changes.gone, std::vector<std::uint32_t>{2});
  EXPECT_TRUE(loader.take_new(state).gone.empty()) << "let go once";
}

TEST(AppearanceLoader, APackageThatCannotBeShownLeavesTheGenericFace) {
  render::RendererOptions options;
  options.width = options.height = 32;
  options.samples = 0;
  std::string error;
  auto view = RoomView::create(options, error);
  ASSERT_TRUE(view) << error;
  RoomState state;
  std::ostringstream log;
  AppearanceLoader loader(log);
  give_package(state, 4, Bytes(64, 9));
  loader.load_new(state, *view);
  EXPECT_EQ(log.str().rfind("avatar 4: its package cannot be shown (", 0), 0u) << log.str();
  EXPECT_NE(log.str().find("drawing the generic face"), std::string::npos);
}

}  // namespace
}  // namespace fw::client
