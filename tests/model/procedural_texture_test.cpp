#include "fw/model/procedural_texture.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace fw::model {
namespace {

// The texel of `image` that model-frame point `p` maps to.
const std::uint8_t* texel_at(const RgbaImage& image, const GenericFace& face, glm::vec2 p) {
  const glm::vec2 uv = face.texture_frame.to_uv(p);
  const int x = static_cast<int>(uv.x * static_cast<float>(image.width));
  const int y = static_cast<int>((1.0f - uv.y) * static_cast<float>(image.height));
  return image.at(x, y);
}

float redness(const std::uint8_t* px) { return static_cast<float>(px[0]) / (1.0f + px[1]); }

TEST(ProceduralTexture, SkinHasHolesExactlyAtTheEyes) {
  const GenericFace& face = generic_face();
  const RgbaImage skin = make_skin_texture(face, Appearance{}, 256);
  EXPECT_EQ(skin.width, 256);
  EXPECT_EQ(texel_at(skin, face, {-0.5f, 0.0f})[3], 0) << "right eye";
  EXPECT_EQ(texel_at(skin, face, {0.5f, 0.0f})[3], 0) << "left eye";
  EXPECT_EQ(texel_at(skin, face, {0.0f, 0.8f})[3], 255) << "forehead";
  EXPECT_EQ(texel_at(skin, face, {0.0f, -0.3f})[3], 255) << "nose";
}

TEST(ProceduralTexture, LipsAreRedderThanCheeksAndHairIsDark) {
  const GenericFace& face = generic_face();
  const RgbaImage skin = make_skin_texture(face, Appearance{}, 256);
  EXPECT_GT(redness(texel_at(skin, face, {0.0f, -1.22f})), redness(texel_at(skin, face, {0.6f, -0.4f})) + 0.2f);
  EXPECT_LT(texel_at(skin, face, {0.0f, 1.5f})[0], texel_at(skin, face, {0.0f, 0.6f})[0] - 60) << "hair vs forehead";
}

// The relief a low-polygon mesh cannot shade is painted in: the eye
// sockets, the crease of each upper lid and the underside of the nose are
// darker than the open cheek and forehead, and the upper lip darker than the
// lower. Without it a procedural face read as a flat mask.
TEST(ProceduralTexture, HollowsOfTheFaceAreShaded) {
  const GenericFace& face = generic_face();
  const RgbaImage skin = make_skin_texture(face, Appearance{}, 256);
  const auto red = [&](glm::vec2 p) { return static_cast<int>(texel_at(skin, face, p)[0]); };
  const int forehead = red({0.0f, 0.7f}), cheek = red({0.75f, -0.55f});
  for (const float side : {-1.0f, 1.0f}) {
    EXPECT_LT(red({side * 0.42f, 0.16f}) + 15, forehead) << "eye socket, side " << side;
  }
  EXPECT_LT(red({0.07f, -0.8f}) + 20, cheek) << "under the nose";
  EXPECT_LT(red({0.0f, -1.38f}) + 12, cheek) << "under the lower lip";
  EXPECT_LT(red({0.15f, -1.03f}) + 15, red({0.15f, -1.2f})) << "upper lip against lower lip";
}

TEST(ProceduralTexture, FollowsTheAppearance) {
  const GenericFace& face = generic_face();
  Appearance dark;
  dark.skin = {0.45f, 0.3f, 0.22f};
  const RgbaImage light_skin = make_skin_texture(face, Appearance{}, 64);
  const RgbaImage dark_skin = make_skin_texture(face, dark, 64);
  EXPECT_LT(texel_at(dark_skin, face, {0.0f, 0.6f})[0] + 60, texel_at(light_skin, face, {0.0f, 0.6f})[0]);
}

TEST(ProceduralTexture, EyeHasPupilIrisAndSclera) {
  const GenericFace& face = generic_face();
  Appearance look;
  look.iris = {0.1f, 0.6f, 0.2f};  // green
  const RgbaImage eye = make_eye_texture(face.eyes[0], look, 128);
  const std::uint8_t* pupil = eye.at(64, 64);
  EXPECT_LT(pupil[0] + pupil[1] + pupil[2], 60);
  // The iris ring lies at about 3/4 of the iris angle from the centre.
  const float iris_angle = std::asin(5.85f / 63.0f / face.eyes[0].radius);
  const int r = static_cast<int>(0.75f * iris_angle / face.eyes[0].cap_angle_rad * 64.0f);
  const std::uint8_t* iris = eye.at(64 + r, 64);
  EXPECT_GT(iris[1], iris[0] + 20) << "green iris";
  const std::uint8_t* sclera = eye.at(64 + 30, 64);
  EXPECT_GT(sclera[0], 180);
  EXPECT_GT(sclera[1], 180);
}

TEST(ProceduralTexture, MouthIsDarkWithTeethBelowTheLipLine) {
  const RgbaImage mouth = make_mouth_texture(128, 64);
  EXPECT_LT(mouth.at(64, 5)[0], 90) << "cavity above the teeth";
  const int teeth_row = static_cast<int>((1.0f - 0.42f) * 64.0f);
  EXPECT_GT(mouth.at(60, teeth_row)[0], 150) << "teeth";
}

}  // namespace
}  // namespace fw::model
