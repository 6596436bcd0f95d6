// What makes a found face unusable, on landmarks made in code: turned or
// tilted past the limit or not, any roll, eyes shut.
#include "pose_checks.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "fw/model/landmark_template.hpp"

namespace fw::photo {
namespace {

namespace lm = model::landmarks;

// The template's landmarks (model frame), and the same in the pixels of a
// 600x600 photo: 100 px to a model unit, y down.
struct Face {
  ModelLandmarks model{};
  PhotoLandmarks photo{};
  cv::Rect box{170, 180, 260, 260};
};

Face template_face() {
  Face f;
  const auto tmpl = model::landmark_template();
  for (std::size_t i = 0; i < f.model.size(); ++i) {
    f.model[i] = tmpl[i];
    f.photo[i] = {300.0f + 100.0f * tmpl[i].x, 250.0f - 100.0f * tmpl[i].y};
  }
  return f;
}

// The nose tip moved sideways as a head turned `degrees` moves it.
Face turned(float degrees) {
  Face f = template_face();
  const float width = f.model[lm::kJawEnd - 1].x - f.model[lm::kJawBegin].x;
  const float mid = 0.5f * (f.model[lm::kJawEnd - 1].x + f.model[lm::kJawBegin].x);
  f.model[lm::kNoseTip].x = mid + 0.655f * std::tan(degrees * std::numbers::pi_v<float> / 180.0f) * width;
  return f;
}

std::optional<PrepError> check(const Face& f, float pitch_deg = 0.0f) {
  return check_face(f.box, f.photo, cv::Size(600, 600), f.model, pitch_deg);
}

TEST(PoseChecks, AFrontalFaceIsUsable) {
  const auto problem = check(template_face());
  EXPECT_FALSE(problem.has_value()) << problem->message;
  EXPECT_NEAR(estimate_yaw_deg(template_face().model), 0.0f, 0.5f);
}

TEST(PoseChecks, TurnedUpTo35DegreesIsUsableAndFartherIsRefusedWithAdvice) {
  for (const float degrees : {-30.0f, 20.0f, 33.0f}) {
    const auto problem = check(turned(degrees));
    EXPECT_FALSE(problem.has_value()) << degrees << ": " << problem->message;
  }
  for (const float degrees : {-40.0f, 38.0f}) {
    const auto problem = check(turned(degrees));
    ASSERT_TRUE(problem.has_value()) << degrees;
    EXPECT_EQ(problem->code, PrepErrorCode::head_turned);
    EXPECT_NE(problem->message.find("use a photo facing the camera (within about 35 degrees)"), std::string::npos)
        << problem->message;
  }
}

TEST(PoseChecks, TiltedUpTo35DegreesIsUsableAndFartherIsRefusedWithAdvice) {
  for (const float degrees : {-33.0f, -20.0f, 25.0f, 34.0f}) {
    const auto problem = check(template_face(), degrees);
    EXPECT_FALSE(problem.has_value()) << degrees << ": " << problem->message;
  }
  for (const auto& [degrees, words] : {std::pair{40.0f, "tilted back about 40 degrees"},
                                       std::pair{-37.0f, "tilted down about 37 degrees"}}) {
    const auto problem = check(template_face(), degrees);
    ASSERT_TRUE(problem.has_value()) << degrees;
    EXPECT_EQ(problem->code, PrepErrorCode::head_tilted);
    EXPECT_NE(problem->message.find(words), std::string::npos) << problem->message;
    EXPECT_NE(problem->message.find("level with the camera (within about 35 degrees)"), std::string::npos)
        << problem->message;
  }
}

TEST(PoseChecks, ShutEyesAreRefusedWithAdvice) {
  Face f = template_face();
  for (const int begin : {lm::kEyeRightBegin, lm::kEyeLeftBegin})
    for (const int i : {1, 2, 4, 5}) f.model[static_cast<std::size_t>(begin + i)].y = f.model[static_cast<std::size_t>(begin)].y;
  const auto problem = check(f);
  ASSERT_TRUE(problem.has_value());
  EXPECT_EQ(problem->code, PrepErrorCode::eyes_closed);
  EXPECT_NE(problem->message.find("open eyes"), std::string::npos) << problem->message;
}

}  // namespace
}  // namespace fw::photo
