#include "fw/render/camera.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace fw::render {
namespace {

glm::vec3 apply(const glm::mat4& m, glm::vec3 p) { return glm::vec3(m * glm::vec4(p, 1.0f)); }

TEST(Camera, PortraitSeesTheWholeFace) {
  const Camera camera = Camera::portrait(1.0f);
  for (glm::vec3 p : {glm::vec3(-1.4f, 0.0f, 0.6f), glm::vec3(1.4f, 0.0f, 0.6f), glm::vec3(0.0f, 1.6f, 0.3f),
                      glm::vec3(0.0f, -2.1f, 0.3f)}) {
    const glm::vec3 px = project_to_pixel(camera, p, 100, 100);
    EXPECT_GT(px.x, 0.0f);
    EXPECT_LT(px.x, 100.0f);
    EXPECT_GT(px.y, 0.0f);
    EXPECT_LT(px.y, 100.0f);
  }
}

TEST(Camera, ProjectionPutsUpAtTheTopAndRightAtTheRight) {
  const Camera camera = Camera::portrait(1.0f);
  const glm::vec3 centre = project_to_pixel(camera, {0, -0.25f, 0}, 200, 200);
  EXPECT_NEAR(centre.x, 100.0f, 1e-3f);
  EXPECT_NEAR(centre.y, 100.0f, 1e-3f);
  EXPECT_LT(project_to_pixel(camera, {0, 1, 0}, 200, 200).y, 100.0f);
  EXPECT_GT(project_to_pixel(camera, {1, 0, 0}, 200, 200).x, 100.0f);
}

TEST(HeadTransform, IdentityAtRest) {
  const glm::mat4 m = head_transform({});
  EXPECT_NEAR(glm::length(apply(m, {0.3f, 0.2f, 1.0f}) - glm::vec3(0.3f, 0.2f, 1.0f)), 0.0f, 1e-6f);
}

TEST(HeadTransform, SignsFollowFaceParams) {
  const glm::vec3 nose(0.0f, -0.56f, 1.4f);
  HeadPose yaw, pitch, roll;
  yaw.yaw_rad = 0.3f;
  pitch.pitch_rad = 0.3f;
  roll.roll_rad = 0.3f;
  EXPECT_GT(apply(head_transform(yaw), nose).x, 0.2f) << "yaw: nose toward the person's left (+x)";
  EXPECT_GT(apply(head_transform(pitch), nose).y, nose.y + 0.2f) << "pitch: nose up";
  EXPECT_GT(apply(head_transform(roll), {0, 1.3f, 0.5f}).x, 0.2f) << "roll: crown toward the left shoulder";
}

TEST(HeadTransform, RotatesAboutTheNeckAndKeepsDistances) {
  HeadPose pose;
  pose.yaw_rad = 0.5f;
  pose.pitch_rad = -0.2f;
  pose.roll_rad = 0.1f;
  const glm::mat4 m = head_transform(pose);
  EXPECT_NEAR(glm::length(apply(m, kNeckPivot) - kNeckPivot), 0.0f, 1e-5f);
  const glm::vec3 a(0.5f, 0.0f, 1.0f), b(-0.5f, -1.0f, 0.8f);
  EXPECT_NEAR(glm::length(apply(m, a) - apply(m, b)), glm::length(a - b), 1e-5f);
}

TEST(HeadTransform, TranslatesAndPlaces) {
  HeadPose pose;
  pose.translation = {0.1f, 0.0f, 0.0f};
  const glm::mat4 place = glm::translate(glm::mat4(1.0f), glm::vec3(5, 0, 0));
  EXPECT_NEAR(apply(head_transform(pose, place), {0, 0, 0}).x, 5.1f, 1e-5f);
}

TEST(EyeTransform, TurnsAboutTheEyeCentre) {
  const glm::vec3 centre(0.5f, 0.0f, 0.6f);
  const glm::mat4 m = eye_transform(centre, 0.3f, 0.2f);
  EXPECT_NEAR(glm::length(apply(m, centre) - centre), 0.0f, 1e-6f);
  const glm::vec3 pupil = apply(m, centre + glm::vec3(0, 0, 0.27f));
  EXPECT_GT(pupil.x, centre.x) << "yaw toward the person's left";
  EXPECT_GT(pupil.y, centre.y) << "pitch up";
}

TEST(PlaceInRow, SpreadsFacesSymmetrically) {
  EXPECT_NEAR(apply(place_in_row(0, 1), {0, 0, 0}).x, 0.0f, 1e-6f);
  EXPECT_NEAR(apply(place_in_row(0, 3), {0, 0, 0}).x, -apply(place_in_row(2, 3), {0, 0, 0}).x, 1e-6f);
}

}  // namespace
}  // namespace fw::render
