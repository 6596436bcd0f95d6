// server/avatars/demo_faces.hpp as a viewer receives the residents: each
// package reads, and the whites of the eyes are white (they once took the
// lips' colour when Appearance gained a field, and every resident looked
// bloodshot), while the lips keep each resident's own colour.
#include "demo_faces.hpp"

#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "fw/model/avatar_package.hpp"
#include "fw/render/image_codec.hpp"

namespace fw::server {
namespace {

model::RgbaImage decoded(const model::PackageImage& image) {
  model::RgbaImage pixels;
  std::string error;
  EXPECT_TRUE(render::decode_image(image.bytes, 4096, pixels, error)) << error;
  return pixels;
}

TEST(DemoFaces, TheWhitesOfTheResidentsEyesAreWhite) {
  for (std::uint32_t index = 0; index < 6; ++index) {
    model::AvatarPackage package;
    std::string error;
    ASSERT_TRUE(model::parse_avatar_package(make_demo_package(index), package, error)) << error;
    const model::RgbaImage eye = decoded(package.eye);
    ASSERT_GT(eye.width, 16);
    // The eye texture is polar about the pupil at its centre: a twelfth in
    // from either side, level with the pupil, lies the white beside the iris.
    for (const int x : {eye.width / 12, eye.width - 1 - eye.width / 12}) {
      const std::uint8_t* p = eye.at(x, eye.height / 2);
      const int low = std::min({p[0], p[1], p[2]}), high = std::max({p[0], p[1], p[2]});
      EXPECT_GT(low, 150) << "resident " << index << ": the white is dark or coloured at x " << x;
      EXPECT_LT(high - low, 30) << "resident " << index << ": the white is tinted at x " << x << " ("
                                << int(p[0]) << ", " << int(p[1]) << ", " << int(p[2]) << ")";
    }
  }
}

TEST(DemoFaces, TheResidentsTexturesAreAlbedoForTheRendererToLight) {
  for (std::uint32_t index = 0; index < 3; ++index) {
    model::AvatarPackage package;
    std::string error;
    ASSERT_TRUE(model::parse_avatar_package(make_demo_package(index), package, error)) << error;
    EXPECT_EQ(package.texture_light, model::TextureLight::albedo) << "resident " << index;
  }
}

}  // namespace
}  // namespace fw::server
