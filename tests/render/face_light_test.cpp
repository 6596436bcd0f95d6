// The light of face.frag: procedural (albedo) faces are shaded by the
// renderer's sky, ground and key light; a photo keeps its own light at
// rest; every eye shows a catch-light toward the key light. Pixels are
// found by projecting points of the generic face, not by coordinates.
#include "fw/render/face_renderer.hpp"

#include <algorithm>
#include <array>

#include <gtest/gtest.h>

#include "fw/model/face_reconstruction.hpp"
#include "fw/render/avatar_appearance.hpp"
#include "painted_face.hpp"
#include "pixel_count.hpp"

namespace fw::render {
namespace {

using model::TextureLight;

constexpr int kLightImageSize = 512;
const glm::u8vec3 kLitSkin(181, 122, 94);

class FaceLightTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    std::string error;
    RendererOptions options;
    options.width = options.height = kLightImageSize;
    renderer_ = FaceRenderer::create(options, error).release();
    ASSERT_NE(renderer_, nullptr) << error;
  }
  static void TearDownTestSuite() { delete renderer_; }

  static model::RgbaImage render(const AvatarAppearance& face) {
    const FaceId id = renderer_->add_face(face.avatar.face, face.textures);
    const model::FaceShape shape = model::reconstruct_face(face.avatar, {});
    renderer_->set_face_shape(id, shape.positions, shape.uvs);
    const FaceDraw draw = face_draw(id, {});
    return renderer_->render({&draw, 1}, Camera::portrait(1.0f));
  }

  static glm::vec3 pixel_of(glm::vec3 model_point) {
    return project_to_pixel(Camera::portrait(1.0f), model_point, kLightImageSize, kLightImageSize);
  }

  // Mean linear luminance of the 7x7 pixels over a model-frame point of the
  // skin at rest (its depth taken near the nose's, as the cheeks' is).
  static float luminance_at(const AvatarAppearance& face, const model::RgbaImage& image, glm::vec2 p) {
    const float z = face.avatar.face.skin.positions[face.avatar.face.landmark_vertices[30]].z * 0.85f;
    const glm::vec3 px = pixel_of(glm::vec3(p, z));
    float sum = 0.0f;
    for (int dy = -3; dy <= 3; ++dy)
      for (int dx = -3; dx <= 3; ++dx) {
        const std::uint8_t* c = image.at(static_cast<int>(px.x) + dx, static_cast<int>(px.y) + dy);
        sum += 0.2126f * test::to_linear(c[0]) + 0.7152f * test::to_linear(c[1]) + 0.0722f * test::to_linear(c[2]);
      }
    return sum / 49.0f;
  }

  static inline FaceRenderer* renderer_ = nullptr;
};

// Pairs of skin points mirrored across the face: the first on the side of
// the key light (the viewer's right, +x), the second away from it.
const std::array<std::array<glm::vec2, 2>, 2> kMirroredSkin{{
    {glm::vec2(0.7f, -0.55f), glm::vec2(-0.7f, -0.55f)},  // cheeks
    {glm::vec2(0.55f, 0.8f), glm::vec2(-0.55f, 0.8f)},    // forehead
}};

TEST_F(FaceLightTest, AProceduralFaceIsShadedFromItsLitSideToItsShadowSide) {
  // One colour all over: whatever differs between the sides is the light.
  const AvatarAppearance face = test::flat_face(kLitSkin, TextureLight::albedo);
  const model::RgbaImage image = render(face);
  for (const auto& [lit, shadow] : kMirroredSkin) {
    const float lit_light = luminance_at(face, image, lit), shadow_light = luminance_at(face, image, shadow);
    // Measured 1.37 (cheeks) and 1.33 (forehead); flat, as the photo's
    // relighting left it, was 1.0.
    EXPECT_GT(lit_light, 1.25f * shadow_light) << "at " << lit.x << "," << lit.y;
    // Soft, not a spotlight: the shadow side keeps the sky's and ground's light.
    EXPECT_LT(lit_light, 3.0f * shadow_light) << "at " << lit.x << "," << lit.y;
  }
}

TEST_F(FaceLightTest, APhotoFaceAtRestKeepsItsOwnLightOnBothSides) {
  const AvatarAppearance face = test::flat_face(kLitSkin, TextureLight::photo);
  const model::RgbaImage image = render(face);
  const float texture = 0.2126f * test::to_linear(kLitSkin.r) + 0.7152f * test::to_linear(kLitSkin.g) +
                        0.0722f * test::to_linear(kLitSkin.b);
  for (const auto& pair : kMirroredSkin)
    for (const glm::vec2 p : pair) EXPECT_NEAR(luminance_at(face, image, p), texture, 0.02f * texture) << p.x << "," << p.y;
}

// The eyes in one dark colour (no painted highlight), so that anything near
// white within the iris is the light's.
TEST_F(FaceLightTest, EachEyeShowsASmallCatchLightTowardTheKeyLight) {
  for (const TextureLight light : {TextureLight::photo, TextureLight::albedo}) {
    AvatarAppearance face = test::flat_face(kLitSkin, light);
    model::RgbaImage& eye = face.textures.eye;
    for (int i = 0; i < eye.width * eye.height; ++i) {
      std::uint8_t* p = eye.pixels.data() + 4 * i;
      p[0] = 40, p[1] = 60, p[2] = 100, p[3] = 255;
    }
    const model::RgbaImage image = render(face);
    for (const model::EyeLayer& layer : face.avatar.face.eyes) {
      // The cornea's front: the eyeball's point nearest the camera.
      glm::vec3 front = layer.centre;
      for (const glm::vec3& p : layer.mesh.positions)
        if (p.z > front.z) front = p;
      const glm::vec3 centre = pixel_of(front);
      // The iris: 11.7 mm across, one model unit being 63 mm.
      const float iris_px = pixel_of(front + glm::vec3(5.85f / 63.0f, 0.0f, 0.0f)).x - centre.x;
      ASSERT_GT(iris_px, 5.0f);
      const test::PixelBox iris{static_cast<int>(centre.x - iris_px), static_cast<int>(centre.y - iris_px),
                                static_cast<int>(centre.x + iris_px) + 1, static_cast<int>(centre.y + iris_px) + 1};
      const auto near_white = [](const std::uint8_t* p) { return std::min({p[0], p[1], p[2]}) > 190; };
      const int white = test::count_pixels(image, near_white, iris);
      const int area = (iris.x1 - iris.x0) * (iris.y1 - iris.y0);
      EXPECT_GE(white, 2) << "a catch-light in the eye at x " << centre.x;
      EXPECT_LT(white, area / 10) << "small: a highlight, not a white eye";
      // Toward the key light (above and to the viewer's right): the
      // catch-light's pixels lie right of and above the cornea's front.
      const auto right_and_up = [&](int x0, int y0, int x1, int y1) {
        return test::count_pixels(image, near_white, test::PixelBox{x0, y0, x1, y1});
      };
      EXPECT_EQ(right_and_up(static_cast<int>(centre.x), iris.y0, iris.x1, static_cast<int>(centre.y) + 1), white)
          << "the catch-light lies toward the key light";
    }
  }
}

}  // namespace
}  // namespace fw::render
