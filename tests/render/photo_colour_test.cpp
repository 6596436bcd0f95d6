// Colour as in the photo: the texture is shown as it is, shading changes
// only with the surface's direction, light is mixed and filtered linearly.
#include <array>
#include <cmath>
#include <cstdint>

#include <gtest/gtest.h>

#include "fw/model/face_reconstruction.hpp"
#include "fw/render/avatar_appearance.hpp"
#include "painted_face.hpp"

namespace fw::render {
namespace {

constexpr int kImageSize = 256, kSmallImageSize = 96;

using test::flat_face;
using test::painted_face;
using test::to_linear;

class PhotoColourTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    std::string error;
    RendererOptions options;
    options.width = options.height = kImageSize;
    renderer_ = FaceRenderer::create(options, error).release();
    ASSERT_NE(renderer_, nullptr) << error;
    options.width = options.height = kSmallImageSize;
    small_renderer_ = FaceRenderer::create(options, error).release();
    ASSERT_NE(small_renderer_, nullptr) << error;
  }
  static void TearDownTestSuite() {
    delete renderer_;
    delete small_renderer_;
  }

  static model::RgbaImage render(const AvatarAppearance& face, const codec::FaceParams& params = {},
                                 FaceRenderer* renderer = renderer_) {
    const FaceId id = renderer->add_face(face.avatar.face, face.textures);
    const model::FaceShape shape = model::reconstruct_face(face.avatar, params);
    renderer->set_face_shape(id, shape.positions, shape.uvs);
    const FaceDraw draw = face_draw(id, params);
    return renderer->render({&draw, 1}, Camera::portrait(1.0f));
  }

  // The pixel over a model-frame point of the face at rest.
  static glm::ivec2 pixel(const AvatarAppearance& face, glm::vec2 p, int image_size = kImageSize) {
    const float z = face.avatar.face.skin.positions[face.avatar.face.landmark_vertices[30]].z;
    const glm::vec3 px = project_to_pixel(Camera::portrait(1.0f), glm::vec3(p, z * 0.85f), image_size, image_size);
    return {static_cast<int>(px.x), static_cast<int>(px.y)};
  }

  // A flat face of `skin` at rest, facing the camera, shows it within
  // `tolerance` at every skin point.
  static void expect_shown_as_it_is(glm::u8vec3 skin, int tolerance);

  static inline FaceRenderer* renderer_ = nullptr;
  // Small enough that the skin texture is shown several times smaller.
  static inline FaceRenderer* small_renderer_ = nullptr;
};

// Forehead, both cheeks, chin: skin away from the eyes, lips and brows.
const std::array<glm::vec2, 4> kSkinPoints{glm::vec2(0.0f, 0.8f), glm::vec2(0.65f, -0.55f),
                                           glm::vec2(-0.65f, -0.55f), glm::vec2(0.0f, -1.6f)};

void PhotoColourTest::expect_shown_as_it_is(glm::u8vec3 skin, int tolerance) {
  const AvatarAppearance face = flat_face(skin);
  const model::RgbaImage image = render(face);
  for (const glm::vec2 p : kSkinPoints) {
    const glm::ivec2 px = pixel(face, p);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(image.at(px.x, px.y)[c], skin[c], tolerance) << p.x << "," << p.y << " channel " << c;
  }
}

TEST_F(PhotoColourTest, AFaceAtRestFacingTheCameraShowsItsTextureAsItIs) {
  // The photo holds its own light: lit a second time, this colour would
  // change with each point's direction to the key light.
  expect_shown_as_it_is({181, 122, 94}, 3);
}

TEST_F(PhotoColourTest, TheDarkestColoursKeepTheirSteps) {
  // In eight bits of linear light these sRGB values would all round to
  // black: the colour textures must keep finer steps near black.
  expect_shown_as_it_is({4, 3, 2}, 1);
}

TEST_F(PhotoColourTest, TurningTheHeadShadesTheSideTurnedFromTheLight) {
  const glm::u8vec3 skin(181, 122, 94);
  const AvatarAppearance face = flat_face(skin);
  codec::FaceParams turned;
  // The key light is to the viewer's right: a head turned to its own right
  // (negative yaw) shows the viewer its left cheek, turned from the light.
  turned.head_yaw_rad = -0.6f;
  const model::RgbaImage image = render(face, turned);
  int darker = 0, skin_pixels = 0;
  for (int y = 0; y < kImageSize; ++y)
    for (int x = 0; x < kImageSize; ++x) {
      const std::uint8_t* p = image.at(x, y);
      if (p[0] < 60) continue;  // background, eyes, mouth
      ++skin_pixels;
      darker += p[0] < skin.r - 12;
    }
  ASSERT_GT(skin_pixels, 2000);
  EXPECT_GT(darker, skin_pixels / 10) << "a turned head is shaded where it turned away from the light";
}

// A photo's texels at a grazing angle (the sides of a head, seen from the
// front) hold the photo's broad light, not the little that the key light
// alone would leave there: relit by the full ratio of the key's light on
// them now to then, the side of a head turned toward the light came out
// up to 1.6 times as bright as the photo, a pale mask's rim.
TEST_F(PhotoColourTest, TurningTheHeadTowardTheLightBrightensThePhotoLittle) {
  const glm::u8vec3 skin(181, 122, 94);
  const AvatarAppearance face = flat_face(skin);
  codec::FaceParams turned;
  turned.head_yaw_rad = 1.0f;  // toward the key light, its left side (at rest in shadow) now lit
  const model::RgbaImage image = render(face, turned);
  int skin_pixels = 0, brighter = 0;
  for (int y = 0; y < kImageSize; ++y)
    for (int x = 0; x < kImageSize; ++x) {
      const std::uint8_t* p = image.at(x, y);
      if (p[0] < 60) continue;  // background, eyes, mouth
      ++skin_pixels;
      // 1.1 times the texture's light is red 189; 1.6 times, 224.
      brighter += to_linear(p[0]) > 1.12f * to_linear(skin.r);
    }
  ASSERT_GT(skin_pixels, 2000);
  EXPECT_LT(brighter, skin_pixels / 100) << "of " << skin_pixels << " skin pixels";
}

TEST_F(PhotoColourTest, TexturesAreFilteredAndWrittenInLinearLight) {
  // Single-texel black and white stripes, shown several times smaller than
  // the texture: each pixel averages many texels. In light, half black and
  // half white is 0.5, which sRGB writes as 188; averaging the encoded
  // values instead would give about 128.
  const AvatarAppearance face = painted_face([](int x, int) {
    const std::uint8_t v = x % 2 ? 255 : 0;
    return glm::u8vec3(v);
  });
  ASSERT_GE(face.textures.skin.width, 512) << "stripes must be finer than the pixels they land on";
  const model::RgbaImage image = render(face, {}, small_renderer_);
  for (const glm::vec2 p : {glm::vec2(0.0f, 0.8f), glm::vec2(0.0f, -1.6f)}) {
    const glm::ivec2 px = pixel(face, p, kSmallImageSize);
    EXPECT_NEAR(image.at(px.x, px.y)[1], 188, 14) << p.x << "," << p.y;
  }
}

TEST_F(PhotoColourTest, ABlushIsTheSameLightAbsorbedOnDarkAndFairSkin) {
  // Blood absorbs a share of the light that passes through it, whatever the
  // skin's own colour: in linear light, blushing multiplies each channel by
  // the same factor on dark and on fair skin, green more than red.
  codec::FaceParams blush;
  blush.blush[static_cast<std::size_t>(codec::ColourRegion::cheek_left)] = 1.0f;
  const auto factors = [&](glm::u8vec3 rgb) {
    const AvatarAppearance face = flat_face(rgb);
    const model::RgbaImage before = render(face), after = render(face, blush);
    const glm::ivec2 px = pixel(face, {0.65f, -0.55f});
    glm::vec3 factor;
    for (int c = 0; c < 3; ++c) factor[c] = to_linear(after.at(px.x, px.y)[c]) / to_linear(before.at(px.x, px.y)[c]);
    return factor;
  };
  const glm::vec3 dark = factors({96, 62, 44}), fair = factors({236, 196, 176});
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(dark[c], fair[c], 0.04f) << "channel " << c;
  EXPECT_LT(fair.g, fair.r - 0.15f) << "blood takes green, not red";
  EXPECT_LT(fair.r, 1.0f) << "blood adds no light";
}

}  // namespace
}  // namespace fw::render
