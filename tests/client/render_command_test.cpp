// facewire-client render, run as a person runs it.
#include <filesystem>

#include <gtest/gtest.h>
#include <png.h>

#include "run_command.hpp"

namespace fw::client {
namespace {

using test::bin;
using test::run_command;

std::filesystem::path temp(const std::string& name) { return std::filesystem::temp_directory_path() / name; }

TEST(RenderCommand, RendersTheGenericFaceToAPng) {
  const auto out = temp("facewire_client_generic.png");
  std::filesystem::remove(out);
  const auto result = run_command(bin("facewire-client") + " render --generic -o " + out.string() +
                                  " --size 200x160 --yaw 20 --pitch -5 --roll 3");
  ASSERT_EQ(result.status, 0) << result.output;
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  ASSERT_TRUE(png_image_begin_read_from_file(&png, out.c_str()));
  EXPECT_EQ(png.width, 200u);
  EXPECT_EQ(png.height, 160u);
  png_image_free(&png);
  std::filesystem::remove(out);
}

TEST(RenderCommand, BadSizeIsExplained) {
  const auto result = run_command(bin("facewire-client") + " render --generic -o /tmp/x.png --size big");
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.output.find("--size must look like 512x512"), std::string::npos) << result.output;
}

TEST(RenderCommand, OutOfRangeSizeIsExplained) {
  const auto result = run_command(bin("facewire-client") + " render --generic -o /tmp/x.png --size 9999x10");
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.output.find("16..4096"), std::string::npos) << result.output;
}

TEST(RenderCommand, UnwritableOutputIsExplainedAndNothingWritten) {
  const auto result = run_command(bin("facewire-client") + " render --generic -o /no/such/dir/face.png");
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.output.find("cannot write /no/such/dir/face.png"), std::string::npos) << result.output;
}

TEST(RenderCommand, AngleOutOfRangeIsRefused) {
  const auto result = run_command(bin("facewire-client") + " render --generic -o /tmp/x.png --yaw 400");
  EXPECT_NE(result.status, 0);
  EXPECT_NE(result.output.find("--yaw"), std::string::npos) << result.output;
}

TEST(RenderCommand, NothingToRenderIsExplained) {
  const auto result = run_command(bin("facewire-client") + " render -o /tmp/x.png");
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.output.find("--generic"), std::string::npos) << result.output;
}

TEST(RenderCommand, UnbuiltPartsSaySoInsteadOfPretending) {
  auto result = run_command(bin("facewire-client") + " render --avatar a.fwa -o /tmp/x.png");
  EXPECT_EQ(result.status, 3);
  EXPECT_NE(result.output.find("not yet built"), std::string::npos) << result.output;
  result = run_command(bin("facewire-client") + " join ws://127.0.0.1:1/ --room r --name n");
  EXPECT_EQ(result.status, 3);
  EXPECT_NE(result.output.find("not yet built"), std::string::npos) << result.output;
}

}  // namespace
}  // namespace fw::client
