#include "frame_outputs.hpp"

#include <cstdlib>
#include <filesystem>

#include <unistd.h>

#include <gtest/gtest.h>

namespace fw::client {
namespace {

namespace fs = std::filesystem;

// A sink that takes frames until it is told to fail.
class CountingSink : public FrameSink {
 public:
  explicit CountingSink(int* count, bool fails = false) : count_(count), fails_(fails) {}
  bool write(const model::RgbaImage&, std::string& error) override {
    ++*count_;
    if (fails_) error = "the disk is full";
    return !fails_;
  }

 private:
  int* count_;
  bool fails_;
};

class FrameOutputsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("fw_frame_outputs_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
  JoinArgs args_;
  std::string error_;
};

TEST_F(FrameOutputsTest, NothingAskedNothingOpened) {
  FrameOutputs outputs;
  ASSERT_TRUE(open_frame_outputs(args_, 32, 16, outputs, error_)) << error_;
  EXPECT_TRUE(outputs.empty());
}

TEST_F(FrameOutputsTest, EveryFrameGoesToEveryOutputAskedFor) {
  args_.out_dir = (dir_ / "frames").string();
  args_.y4m = (dir_ / "room.y4m").string();
  FrameOutputs outputs;
  ASSERT_TRUE(open_frame_outputs(args_, 32, 16, outputs, error_)) << error_;
  EXPECT_EQ(outputs.sinks.size(), 2u);
  EXPECT_FALSE(outputs.video_on_stdout);
  ASSERT_TRUE(outputs.write(model::RgbaImage(32, 16), error_)) << error_;
  ASSERT_TRUE(outputs.write(model::RgbaImage(32, 16), error_)) << error_;
  outputs.sinks.clear();  // flushes the video
  EXPECT_TRUE(fs::exists(dir_ / "frames" / "frame_000002.png"));
  // Two 4:2:0 frames of 32x16 after the stream header, each with its "FRAME\n".
  EXPECT_GT(fs::file_size(dir_ / "room.y4m"), 2 * (32 * 16 * 3 / 2 + 6));
}

TEST_F(FrameOutputsTest, AnOutputThatCannotOpenSaysWhichFlag) {
  args_.out_dir = "/proc/facewire/cannot/be/here";
  FrameOutputs outputs;
  EXPECT_FALSE(open_frame_outputs(args_, 32, 16, outputs, error_));
  EXPECT_EQ(error_.rfind("--out ", 0), 0u) << error_;
  args_ = {};
  args_.y4m = (dir_ / "odd.y4m").string();
  EXPECT_FALSE(open_frame_outputs(args_, 31, 16, outputs, error_));
  EXPECT_EQ(error_.rfind("--y4m ", 0), 0u) << error_;
}

TEST_F(FrameOutputsTest, AWindowNeedsADisplay) {
  const char* display = std::getenv("DISPLAY");
  if (display && *display) GTEST_SKIP() << "a display is there";
  args_.window = true;
  FrameOutputs outputs;
  EXPECT_FALSE(open_frame_outputs(args_, 32, 16, outputs, error_));
  EXPECT_EQ(error_.rfind("--window", 0), 0u) << error_;
}

TEST_F(FrameOutputsTest, AFailingOutputIsReportedAndTheOthersStillWrite) {
  int first = 0, failing = 0, last = 0;
  FrameOutputs outputs;
  outputs.sinks.push_back(std::make_unique<CountingSink>(&first));
  outputs.sinks.push_back(std::make_unique<CountingSink>(&failing, true));
  outputs.sinks.push_back(std::make_unique<CountingSink>(&last));
  EXPECT_FALSE(outputs.write(model::RgbaImage(4, 4), error_));
  EXPECT_EQ(error_, "the disk is full");
  EXPECT_EQ(first + failing + last, 3);
}

}  // namespace
}  // namespace fw::client
