// Stored files written whole or not at all: the bytes in place, no
// temporary file left behind, writers of one path at once that do not tear
// each other's file, and the leftovers of a crash removed when the store
// opens.
#include "durable_file.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "avatar_store.hpp"
#include "file_bytes.hpp"

namespace fw::server {
namespace {

class DurableFile : public ::testing::Test {
 protected:
  void SetUp() override { std::filesystem::create_directories(directory_); }
  void TearDown() override { std::filesystem::remove_all(directory_); }

  std::vector<std::string> names() const {
    std::vector<std::string> found;
    for (const auto& entry : std::filesystem::directory_iterator(directory_))
      found.push_back(entry.path().filename().string());
    std::sort(found.begin(), found.end());
    return found;
  }

  const std::filesystem::path directory_ =
      std::filesystem::temp_directory_path() / ("fw-durable-" + std::to_string(::getpid()));
};

TEST_F(DurableFile, WritesTheWholeFileAndLeavesNothingElse) {
  const std::vector<std::uint8_t> bytes(300'000, 7);
  std::string error;
  ASSERT_TRUE(write_file_durably(directory_ / "a.fwa", bytes, error)) << error;
  EXPECT_EQ(test::file_bytes(directory_ / "a.fwa"), bytes);
  const std::vector<std::uint8_t> shorter{1, 2, 3};
  ASSERT_TRUE(write_file_durably(directory_ / "a.fwa", shorter, error)) << error;
  EXPECT_EQ(test::file_bytes(directory_ / "a.fwa"), shorter) << "replaced whole, not overwritten in place";
  EXPECT_EQ(names(), std::vector<std::string>{"a.fwa"});
  struct stat status {};
  ASSERT_EQ(::stat((directory_ / "a.fwa").c_str(), &status), 0);
  EXPECT_EQ(status.st_mode & 077, 0u) << "photos are readable by the server's user alone";
}

TEST_F(DurableFile, AFailedWriteSaysWhyAndLeavesNothing) {
  std::string error;
  EXPECT_FALSE(write_file_durably(directory_ / "missing" / "a.fwa", std::vector<std::uint8_t>{1}, error));
  EXPECT_NE(error.find("missing/a.fwa"), std::string::npos) << error;
  EXPECT_NE(error.find("writable"), std::string::npos) << error;
  EXPECT_TRUE(names().empty());
}

// Two uploads of the same photo prepared at once store the same files: each
// writer has a temporary file of its own, so every write succeeds and the
// file is always one writer's whole bytes.
TEST_F(DurableFile, WritersOfOnePathAtOnceDoNotTearIt) {
  constexpr int kWriters = 4, kWrites = 50;
  std::atomic<int> failures{0};
  std::vector<std::thread> writers;
  for (int w = 0; w < kWriters; ++w)
    writers.emplace_back([&, w] {
      const std::vector<std::uint8_t> bytes(64 * 1024 + w * 1000, static_cast<std::uint8_t>('a' + w));
      std::string error;
      for (int i = 0; i < kWrites; ++i)
        if (!write_file_durably(directory_ / "same.fwa", bytes, error)) ++failures;
    });
  for (auto& writer : writers) writer.join();
  EXPECT_EQ(failures, 0);
  const auto bytes = test::file_bytes(directory_ / "same.fwa");
  ASSERT_FALSE(bytes.empty());
  const int writer = bytes.front() - 'a';
  ASSERT_GE(writer, 0);
  ASSERT_LT(writer, kWriters);
  EXPECT_EQ(bytes, std::vector<std::uint8_t>(64 * 1024 + writer * 1000, bytes.front())) << "one writer's bytes, whole";
  EXPECT_EQ(names(), std::vector<std::string>{"same.fwa"});
}

TEST_F(DurableFile, TheStoreRemovesWhatACrashLeftMidWrite) {
  const auto avatars = directory_ / "avatars";
  std::filesystem::create_directories(avatars);
  const std::vector<std::uint8_t> partial(100, 1);
  const std::string asset(32, 'a');
  test::write_file_bytes(avatars / ("." + asset + ".fwa.tmp-Ab12Cd"), partial);
  test::write_file_bytes(avatars / (asset + ".photo.partial-4242"), partial);  // an older build's
  test::write_file_bytes(avatars / (asset + ".photo"), partial);               // a stored file stays
  // Left by a crash an hour ago: a temporary file written a moment ago may
  // be another process's write under way, and stays.
  const auto an_hour_ago = std::filesystem::file_time_type::clock::now() - std::chrono::hours(1);
  std::filesystem::last_write_time(avatars / ("." + asset + ".fwa.tmp-Ab12Cd"), an_hour_ago);
  std::filesystem::last_write_time(avatars / (asset + ".photo.partial-4242"), an_hour_ago);
  test::write_file_bytes(avatars / ("." + asset + ".preview.fwa.tmp-Zz99Yy"), partial);
  Metrics metrics;
  std::string error;
  AvatarStore store(directory_, metrics, error);
  ASSERT_TRUE(error.empty()) << error;
  std::vector<std::string> left;
  for (const auto& entry : std::filesystem::directory_iterator(avatars))
    left.push_back(entry.path().filename().string());
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"." + asset + ".preview.fwa.tmp-Zz99Yy", asset + ".photo"}));
}

TEST(TemporaryFileName, IsOnlyTheNamesWritersGive) {
  EXPECT_TRUE(is_temporary_file_name(".0123.fwa.tmp-x8Yz12"));
  EXPECT_TRUE(is_temporary_file_name("0123.fwa.partial-17"));
  EXPECT_FALSE(is_temporary_file_name("0123.fwa"));
  EXPECT_FALSE(is_temporary_file_name("0123.preview.fwa"));
  EXPECT_FALSE(is_temporary_file_name("0123.partial-"));
  EXPECT_FALSE(is_temporary_file_name("0123.partial-x"));
}

}  // namespace
}  // namespace fw::server
