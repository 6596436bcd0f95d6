// Saved looks (look_store.hpp, saved_looks.hpp) on real files in a
// temporary directory, without sockets: names held to the display names'
// rules, the file read back as written and a damaged one ignored, at most
// 16 looks, and the looks gone with their avatar, whether its uploader
// deletes it or the retention sweep does.
#include "look_store.hpp"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "avatar_retention.hpp"
#include "avatar_store.hpp"
#include "demo_faces.hpp"

namespace fw::server {
namespace {

TEST(SavedLookNames, AreVisibleTextOfAtMost32Bytes) {
  std::string name;
  EXPECT_EQ(normalize_look_name("blush slowly", name), "");
  EXPECT_EQ(name, "blush slowly");
  EXPECT_EQ(normalize_look_name("Cafe\xCC\x81", name), "") << "a combining accent";
  EXPECT_EQ(name, "Caf\xC3\xA9") << "kept in NFC, as display names are";
  EXPECT_NE(normalize_look_name("", name), "");
  EXPECT_NE(normalize_look_name("   ", name).find("visible"), std::string::npos);
  EXPECT_NE(normalize_look_name("a\xE2\x80\x8B", name).find("invisible"), std::string::npos) << "a zero-width space";
  EXPECT_NE(normalize_look_name("a\nb", name), "");
  EXPECT_EQ(normalize_look_name(std::string(32, 'x'), name), "");
  EXPECT_NE(normalize_look_name(std::string(33, 'x'), name).find("at most 32"), std::string::npos);
}

TEST(SavedLookFiles, ReadBackAsWrittenAndADamagedOneIsNone) {
  const std::vector<SavedLook> looks{{"a", "ClearAllFrame\n"}, {"b c", ""}, {"d", std::string(4096, '#')}};
  std::vector<SavedLook> back;
  ASSERT_TRUE(decode_looks(encode_looks(looks), back));
  EXPECT_EQ(back, looks);
  ASSERT_TRUE(decode_looks(encode_looks({}), back));
  EXPECT_TRUE(back.empty());
  const std::string bytes = encode_looks(looks);
  for (const std::size_t cut : {bytes.size() - 1, bytes.size() / 2, std::size_t{3}})
    EXPECT_FALSE(decode_looks(bytes.substr(0, cut), back)) << "cut at " << cut;
  EXPECT_TRUE(back.empty());
  EXPECT_FALSE(decode_looks("facewire looks 1\n99999 1\nx\n", back));
}

class LookStoreDirectory : public ::testing::Test {
 protected:
  void TearDown() override { std::filesystem::remove_all(data_); }
  const std::filesystem::path data_ = std::filesystem::temp_directory_path() /
                                      ("fw_look_store_test_" + std::to_string(::getpid()) + "_" +
                                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
  Metrics metrics_;
};

TEST_F(LookStoreDirectory, KeepsSixteenLooksAndReplacesOneByName) {
  std::string error;
  AvatarStore avatars(data_, metrics_, error);
  ASSERT_EQ(error, "");
  const auto avatar = avatars.put(make_demo_package(1), error);
  ASSERT_TRUE(avatar) << error;
  LookStore looks(avatars.directory());
  for (std::size_t i = 0; i < kMaxLooksPerAvatar; ++i)
    ASSERT_EQ(looks.put(avatar->asset, {"look " + std::to_string(i), "script " + std::to_string(i)}, error),
              LookChange::done);
  EXPECT_EQ(looks.put(avatar->asset, {"one more", "x"}, error), LookChange::full);
  EXPECT_NE(error.find("at most 16"), std::string::npos) << error;
  EXPECT_EQ(looks.put(avatar->asset, {"look 3", "again"}, error), LookChange::done);

  // Another store on the same directory (a restart) reads them back.
  LookStore restarted(avatars.directory());
  const auto listed = restarted.list(avatar->asset);
  ASSERT_EQ(listed.size(), kMaxLooksPerAvatar);
  EXPECT_EQ(restarted.find(avatar->asset, "look 3")->script, "again");
  EXPECT_FALSE(restarted.find(avatar->asset, "one more"));
  EXPECT_EQ(restarted.remove(avatar->asset, "look 3", error), LookChange::done);
  EXPECT_EQ(restarted.remove(avatar->asset, "look 3", error), LookChange::unknown_look);
  EXPECT_EQ(looks.list(avatar->asset).size(), kMaxLooksPerAvatar - 1);
  EXPECT_TRUE(looks.list("not an id").empty());
}

TEST_F(LookStoreDirectory, GoWithTheirAvatarWhenDeletedOrSwept) {
  std::string error;
  AvatarStore avatars(data_, metrics_, error);
  LookStore looks(avatars.directory());
  const auto deleted = avatars.put(make_demo_package(1), error);
  const auto stale = avatars.put(make_demo_package(2), error);
  const auto fresh = avatars.put(make_demo_package(3), error);
  ASSERT_TRUE(deleted && stale && fresh) << error;
  for (const auto* avatar : {&*deleted, &*stale, &*fresh})
    ASSERT_EQ(looks.put(avatar->asset, {"smile", "ClearAllFrame\n"}, error), LookChange::done);

  ASSERT_TRUE(avatars.remove(deleted->asset));
  EXPECT_TRUE(looks.list(deleted->asset).empty());
  EXPECT_FALSE(std::filesystem::exists(avatars.directory() / (deleted->asset + ".looks")));

  const auto now = std::filesystem::file_time_type::clock::now();
  std::filesystem::last_write_time(avatars.directory() / (stale->asset + ".fwa"), now - std::chrono::hours(24 * 31));
  const AvatarRetention thirty_days(30);
  EXPECT_EQ(avatars.remove_unused_since(*thirty_days.cutoff(now), {}), std::vector<std::string>{stale->asset});
  EXPECT_TRUE(looks.list(stale->asset).empty()) << "swept with its avatar";
  EXPECT_EQ(looks.list(fresh->asset).size(), 1u);
}

}  // namespace
}  // namespace fw::server
