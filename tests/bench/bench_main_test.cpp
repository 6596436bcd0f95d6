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

TEST(BenchRender, ProfilePrintsMillisecondsPerPartAndVariantForBothScenes) {
  const auto result = test::run_command(test::bin("facewire-bench") + " render --json --profile --seconds 0.1", false);
  ASSERT_EQ(result.status, 0) << result.output;
  const auto json = nlohmann::json::parse(result.output, nullptr, false);
  ASSERT_TRUE(json.is_object()) << result.output;
  for (const char* scene : {"profile_1face_256", "profile_8faces_640x480"}) {
    const auto& profile = json.at(scene);
    EXPECT_GE(profile.at("frames").get<int>(), 3) << scene;
    for (const char* part : {"shape", "clear", "skin", "eyes", "mouth", "shell", "resolve", "readback"})
      EXPECT_GE(profile.at("parts_ms").at(part).get<double>(), 0.0) << scene << " " << part;
    EXPECT_GE(profile.at("variants_ms").at("plain+albedo").get<double>(), 0.0) << scene;
  }
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

TEST(BenchCodec, PrintsBitRatesAndDistortionPerSceneWithARateDistortionTable) {
  const auto result = test::run_command(test::bin("facewire-bench") + " codec --json --no-video 2>/dev/null");
  ASSERT_EQ(result.status, 0) << result.output;
  const auto json = nlohmann::json::parse(result.output, nullptr, false);
  ASSERT_FALSE(json.is_discarded()) << result.output;
  EXPECT_GT(json.at("raw_float32_bps_per_avatar").get<double>(), 40000.0);
  EXPECT_EQ(json.at("paper_bps_per_avatar").get<double>(), 8600.0 * 8 * 30);
  ASSERT_GE(json.at("scenes").size(), 1u);
  for (const auto& scene : json.at("scenes")) {
    for (const char* key : {"name", "bps_mean_per_avatar", "bps_p99_per_avatar", "bits_per_frame_mean", "gaze_max_deg",
                            "idle_bps_mean", "au_max_error", "loss_tolerant", "rms_mm", "max_mm"})
      EXPECT_TRUE(scene.contains(key)) << key;
    // --no-video leaves out the rendered x264 comparison.
    EXPECT_FALSE(scene.contains("x264_over_ours"));
    EXPECT_GT(scene.at("max_mm").get<double>(), scene.at("rms_mm").get<double>());
    EXPECT_GT(scene.at("bps_mean_per_avatar").get<double>(), 0.0);
    EXPECT_GE(scene.at("bps_p99_per_avatar").get<double>(), scene.at("bps_mean_per_avatar").get<double>());
    EXPECT_EQ(scene.at("decode_mismatches").get<int>(), 0);
  }
  EXPECT_GE(json.at("rd_table").at("rows").size(), 5u);
}

TEST(BenchCodec, MeasuresASceneFileAndRefusesABadOne) {
  const std::string scene = ::testing::TempDir() + "bench_codec_scene.fwscene";
  const auto wrote = test::run_command(test::bin("facewire-bench") + " codec --seed 4 --seconds 4 --no-video --write-scene " + scene);
  ASSERT_EQ(wrote.status, 0) << wrote.output;
  const auto result = test::run_command(test::bin("facewire-bench") + " codec --json --no-video --scene " + scene + " 2>/dev/null");
  ASSERT_EQ(result.status, 0) << result.output;
  const auto json = nlohmann::json::parse(result.output, nullptr, false);
  ASSERT_FALSE(json.is_discarded()) << result.output;
  EXPECT_EQ(json.at("scenes").at(0).at("name").get<std::string>(), "bench_codec_scene");
  const auto bad = test::run_command(test::bin("facewire-bench") + " codec --json --scene " + test::bin("facewire-bench"));
  EXPECT_EQ(bad.status, 2) << bad.output;
  EXPECT_NE(bad.output.find("not a scene file"), std::string::npos) << bad.output;
}

TEST(BenchSim, PrintsTheModelSizeSpeedBytesAndResidualForBothSolvers) {
  for (const char* solver : {"massspring", "pbd"}) {
    const auto result = test::run_command(test::bin("facewire-bench") + " sim --faces 4 --seconds 0.2 --threads 2 --solver " +
                                          solver + " --json", false);
    ASSERT_EQ(result.status, 0) << result.output;
    const auto json = nlohmann::json::parse(result.output, nullptr, false);
    ASSERT_TRUE(json.is_object()) << result.output;
    for (const char* key : {"nodes", "springs", "muscles", "elements", "face_frames_per_s", "us_per_face_frame",
                            "bytes_per_face", "residual_rms_mm"})
      EXPECT_TRUE(json.contains(key)) << key;
    EXPECT_GE(json.at("nodes").get<int>(), 1000);
    EXPECT_GE(json.at("springs").get<int>(), 7000);
    EXPECT_EQ(json.at("muscles").get<int>(), 42);
    EXPECT_GE(json.at("elements").get<int>(), 1000);
    EXPECT_GT(json.at("face_frames_per_s").get<double>(), 0.0);
    EXPECT_EQ(json.at("solver").get<std::string>(), solver);
    // The lines played through the tissue: the track's own lips close at
    // its bilabials, so the measure found them.
    ASSERT_TRUE(json.contains("speech_bilabial_gap_mm_track")) << result.output;
    EXPECT_GT(json.at("speech_frames").get<int>(), 200);
    EXPECT_LT(json.at("speech_bilabial_gap_mm_track").get<double>(), 1.0);
    EXPECT_GT(json.at("speech_vs_track_mm").get<double>(), 0.0);
    // Both solvers' skins over the held-out corpus: they simulate one
    // tissue, so they lie nearer each other than either does to the
    // kinematic face.
    ASSERT_TRUE(json.contains("reference_skin_vs_kinematic_mm")) << result.output;
    EXPECT_GT(json.at("reference_skin_vs_kinematic_mm").get<double>(), 0.0);
    EXPECT_LT(json.at("projective_vs_reference_mm").get<double>(), json.at("reference_skin_vs_kinematic_mm").get<double>());
    EXPECT_LT(json.at("projective_vs_reference_mm").get<double>(), json.at("simulated_skin_vs_kinematic_mm").get<double>());
  }
  const auto bad = test::run_command(test::bin("facewire-bench") + " sim --solver verlet --json");
  EXPECT_EQ(bad.status, 2) << bad.output;
  EXPECT_NE(bad.output.find("massspring or pbd"), std::string::npos) << bad.output;
}

}  // namespace
}  // namespace fw::bench

