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

// Runs `facewire-client ARGS` and expects `status` and a message containing `says`.
void expect_refused(const std::string& args, int status, const std::string& says) {
  const auto result = run_command(bin("facewire-client") + " " + args);
  EXPECT_EQ(result.status, status) << args;
  EXPECT_NE(result.output.find(says), std::string::npos) << args << "\n" << result.output;
}

TEST(RenderCommand, BadInputIsExplained) {
  expect_refused("render --generic -o /tmp/x.png --size big", 2, "--size must look like 512x512");
  expect_refused("render --generic -o /tmp/x.png --size 9999x10", 2, "16..4096");
  expect_refused("render -o /tmp/x.png", 2, "--generic");
  expect_refused("render --avatar /no/such.fwa -o /tmp/x.png", 2, "/no/such.fwa: no such file");
}

TEST(RenderCommand, UnwritableOutputIsExplainedAndNothingWritten) {
  expect_refused("render --generic -o /no/such/dir/face.png", 2, "cannot write /no/such/dir/face.png");
  EXPECT_FALSE(std::filesystem::exists("/no/such/dir/face.png"));
}

TEST(RenderCommand, AngleOutOfRangeIsRefused) {
  const auto result = run_command(bin("facewire-client") + " render --generic -o /tmp/x.png --yaw 400");
  EXPECT_NE(result.status, 0);
  EXPECT_NE(result.output.find("--yaw"), std::string::npos) << result.output;
}

TEST(RenderCommand, UnbuiltPartsSaySoInsteadOfPretending) {
  expect_refused("join ws://127.0.0.1:1/ --room r --name n", 3, "not yet built");
}

}  // namespace
}  // namespace fw::client
