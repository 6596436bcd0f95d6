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
                                  " --size 200x160 --head 20,-5,3 --emotion joy=0.7 --au 26=0.3 --gaze 10,5 --lids 0.2,0 --blush cheeks=0.5 --pallor 0.1");
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

TEST(RenderCommand, BadFaceParametersAreExplained) {
  expect_refused("render --generic -o /tmp/x.png --head 400,0,0", 2, "--head: 400");
  expect_refused("render --generic -o /tmp/x.png --gaze 10", 2, "--gaze: expected 2 numbers");
  expect_refused("render --generic -o /tmp/x.png --emotion boredom=1", 2, "unknown emotion 'boredom'");
  expect_refused("render --generic -o /tmp/x.png --emotion joy=2", 2, "VALUE from 0 to 1");
  expect_refused("render --generic -o /tmp/x.png --au 3=0.5", 2, "AU '3' is not one facewire carries");
  expect_refused("render --generic -o /tmp/x.png --au 26L=0.5", 2, "acts on the midline");
  expect_refused("render --generic -o /tmp/x.png --blush ears=0.5", 2, "unknown region 'ears'");
  expect_refused("render --generic -o /tmp/x.png --lids -1,0", 2, "--lids");
  const auto result = run_command(bin("facewire-client") + " render --generic -o /tmp/x.png --yaw 400");
  EXPECT_NE(result.status, 0);
  EXPECT_NE(result.output.find("--yaw"), std::string::npos) << result.output;
}

TEST(RenderCommand, TurnsTheHeadWithSingleAngles) {
  const auto out = temp("facewire_client_yaw.png");
  const auto result = run_command(bin("facewire-client") + " render --generic --yaw 30 --pitch -10 --roll 5 --size 64x64 -o " + out.string());
  EXPECT_EQ(result.status, 0) << result.output;
  std::filesystem::remove(out);
}

TEST(RenderCommand, ContactSheetHasEveryPanel) {
  const auto out = temp("facewire_client_sheet.png");
  const auto result = run_command(bin("facewire-client") + " render --generic --sheet --size 64x64 -o " + out.string());
  ASSERT_EQ(result.status, 0) << result.output;
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  ASSERT_TRUE(png_image_begin_read_from_file(&png, out.c_str()));
  EXPECT_EQ(png.width, 6u * 64) << "six panels to a row";
  EXPECT_EQ(png.height, 3u * 64) << "seventeen panels";
  png_image_free(&png);
  std::filesystem::remove(out);
}

TEST(JoinCommand, BadInputIsExplainedBeforeConnecting) {
  expect_refused("join 127.0.0.1:8080 --room r --name n", 2, "a server URL looks like ws://");
  expect_refused("join ws://127.0.0.1:1/ --room 'a b' --name n", 2, "--room must be");
  expect_refused("join tcp://127.0.0.1:1 --room r --name n --avatar x.fwa", 2, "--api http://HOST:PORT");
  expect_refused("join ws://127.0.0.1:1/ --room r --name n --avatar /nonexistent.fwa", 2, "--avatar");
  expect_refused("join ws://127.0.0.1:1/ --room r --name n --size 15x9", 2, "--size");
  expect_refused("join ws://127.0.0.1:1/ --room r --name n --y4m /dev/null --size 641x360", 2, "even");
  expect_refused("join ws://127.0.0.1:1/ --room r --name n --emote glee", 2, "--emote");
  // Without a display --window says what to use instead.
  const auto result = run_command("env -u DISPLAY " + bin("facewire-client") + " join ws://127.0.0.1:1/ --room r --name n --window");
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.output.find("--out DIR"), std::string::npos) << result.output;
}

TEST(JoinCommand, GivesUpWhenNoServerAnswers) {
  const auto result = run_command(bin("facewire-client") + " join ws://127.0.0.1:1/ --room r --name n --join-timeout 1 -q");
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("could not join room r"), std::string::npos) << result.output;
}

}  // namespace
}  // namespace fw::client
