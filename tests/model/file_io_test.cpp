#include "fw/model/file_io.hpp"

#include <filesystem>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

namespace fw::model {
namespace {

// Each test gets its own directory: ctest runs them as parallel processes, and
// a shared one let one test see the other's temporary file mid-write.
std::filesystem::path test_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return std::filesystem::temp_directory_path() /
         ("facewire_file_io_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
}

TEST(FileIo, WritesAtomicallyAndReadsBack) {
  const auto kDir = test_dir();
  std::filesystem::create_directories(kDir);
  const std::vector<std::uint8_t> data = {1, 2, 3, 4, 5};
  std::string error;
  ASSERT_TRUE(write_file_atomically(kDir / "a.bin", data, error)) << error;
  std::vector<std::uint8_t> back;
  ASSERT_TRUE(read_file(kDir / "a.bin", 100, back, error)) << error;
  EXPECT_EQ(back, data);
  for (const auto& entry : std::filesystem::directory_iterator(kDir))
    EXPECT_EQ(entry.path().filename().string().find("partial"), std::string::npos) << "no temporary left";
  std::filesystem::remove_all(kDir);
}

TEST(FileIo, RefusesTooLargeAndMissingFiles) {
  const auto kDir = test_dir();
  std::filesystem::create_directories(kDir);
  std::string error;
  ASSERT_TRUE(write_file_atomically(kDir / "big.bin", std::vector<std::uint8_t>(50, 7), error));
  std::vector<std::uint8_t> back;
  EXPECT_FALSE(read_file(kDir / "big.bin", 49, back, error));
  EXPECT_NE(error.find("at most 49"), std::string::npos) << error;
  EXPECT_FALSE(read_file(kDir / "none.bin", 49, back, error));
  EXPECT_NE(error.find("no such file"), std::string::npos);
  EXPECT_FALSE(read_file(kDir, 49, back, error)) << "a directory is not a file";
  std::filesystem::remove_all(kDir);
}

TEST(FileIo, FailedWriteLeavesNothing) {
  std::string error;
  EXPECT_FALSE(write_file_atomically("/no/such/dir/x.bin", std::vector<std::uint8_t>{1}, error));
  EXPECT_NE(error.find("cannot write /no/such/dir/x.bin"), std::string::npos);
}

}  // namespace
}  // namespace fw::model
