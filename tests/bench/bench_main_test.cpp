// facewire-bench runs and prints the JSON the issues ask for. Timing values
// are checked for sanity only: benchmarks measure, tests do not time.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "run_command.hpp"

namespace fw::bench {
namespace {

TEST(BenchRender, PrintsOneJsonObjectWithTheAgreedKeys) {
  const auto result = test::run_command(test::bin("facewire-bench") + " render --json --seconds 0.1", false);
  ASSERT_EQ(result.status, 0) << result.output;
  const auto json = nlohmann::json::parse(result.output, nullptr, false);
  ASSERT_FALSE(json.is_discarded()) << result.output;
  ASSERT_TRUE(json.is_object());
  EXPECT_GT(json.at("fps_1face_256").get<double>(), 0.0);
  EXPECT_GT(json.at("fps_8faces_640x480").get<double>(), 0.0);
  EXPECT_FALSE(json.at("renderer").get<std::string>().empty());
}

TEST(BenchPrep, PrintsMillisecondsPerPhotoAndPackageBytes) {
  const auto result = test::run_command(test::bin("facewire-bench") + " prep --json --repeats 1", false);
  ASSERT_EQ(result.status, 0) << result.output;
  const auto json = nlohmann::json::parse(result.output, nullptr, false);
  ASSERT_TRUE(json.is_object()) << result.output;
  EXPECT_GT(json.at("ms_per_photo_median").get<double>(), 0.0);
  EXPECT_GT(json.at("package_bytes").get<int>(), 1000);
  EXPECT_GE(json.at("variants").size(), 5u);
}

TEST(BenchUnbuilt, SaysSoInsteadOfPrintingNumbers) {
  for (const char* name : {"codec", "sim", "fanout"}) {
    const auto result = test::run_command(test::bin("facewire-bench") + " " + name + " --json");
    EXPECT_EQ(result.status, 3) << name;
    EXPECT_NE(result.output.find("not yet built"), std::string::npos) << result.output;
  }
}

}  // namespace
}  // namespace fw::bench
