// The expressive face as it renders: gaze inside a still eye contour, a
// blink of skin, blood in the right places. Pixels, not code.
#include "fw/render/avatar_appearance.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include <gtest/gtest.h>

#include "fw/model/face_reconstruction.hpp"
#include "fw/render/contact_sheet.hpp"

namespace fw::render {
namespace {

constexpr int kImageSize = 384;

class ExpressiveRenderTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    appearance_ = new AvatarAppearance(generic_appearance(model::Appearance{}));
    std::string error;
    RendererOptions options;
    options.width = options.height = kImageSize;
    renderer_ = FaceRenderer::create(options, error).release();
    ASSERT_NE(renderer_, nullptr) << error;
    id_ = renderer_->add_face(appearance_->avatar.face, appearance_->textures);
  }
  static void TearDownTestSuite() {
    delete renderer_;
    delete appearance_;
  }

  static model::RgbaImage render(const codec::FaceParams& params) {
    const model::FaceShape shape = model::reconstruct_face(appearance_->avatar, params);
    renderer_->set_face_shape(id_, shape.positions, shape.uvs);
    const FaceDraw draw = face_draw(id_, params);
    return renderer_->render({&draw, 1}, Camera::portrait(1.0f));
  }

  // Pixel box around a model-frame point (at rest, facing the camera).
  static glm::ivec2 pixel(glm::vec2 p) {
    const float z = appearance_->avatar.face.skin.positions[appearance_->avatar.face.landmark_vertices[30]].z;
    const glm::vec3 px = project_to_pixel(Camera::portrait(1.0f), glm::vec3(p, z * 0.85f), kImageSize, kImageSize);
    return {static_cast<int>(px.x), static_cast<int>(px.y)};
  }

  // The left eye's opening in pixels (its contour landmarks' box).
  static void eye_box(glm::ivec2& low, glm::ivec2& high) {
    const model::GenericFace& face = appearance_->avatar.face;
    glm::vec2 lo(1e9f), hi(-1e9f);
    for (std::uint32_t v : face.eye_holes[static_cast<std::size_t>(model::Side::left)]) {
      const glm::vec3 px = project_to_pixel(Camera::portrait(1.0f), face.skin.positions[v], kImageSize, kImageSize);
      lo = glm::min(lo, glm::vec2(px));
      hi = glm::max(hi, glm::vec2(px));
    }
    low = glm::ivec2(lo) + 1;
    high = glm::ivec2(hi) - 1;
  }

  static inline AvatarAppearance* appearance_ = nullptr;
  static inline FaceRenderer* renderer_ = nullptr;
  static inline FaceId id_ = 0;
};

float luminance(const std::uint8_t* p) { return 0.299f * p[0] + 0.587f * p[1] + 0.114f * p[2]; }

float saturation(const std::uint8_t* p) {
  const float hi = std::max({p[0], p[1], p[2]}), lo = std::min({p[0], p[1], p[2]});
  return hi > 0 ? (hi - lo) / hi : 0.0f;
}

TEST_F(ExpressiveRenderTest, GazeMovesTheIrisInsideAStillEyeContour) {
  glm::ivec2 low, high;
  eye_box(low, high);
  const auto dark_centroid_x = [&](const model::RgbaImage& image) {
    float sum = 0;
    int n = 0;
    for (int y = low.y; y <= high.y; ++y)
      for (int x = low.x; x <= high.x; ++x)
        if (luminance(image.at(x, y)) < 90) sum += static_cast<float>(x), ++n;
    return n ? sum / static_cast<float>(n) : -1.0f;
  };
  codec::FaceParams ahead, left, right;
  left.eye_left = left.eye_right = {-0.45f, 0.0f};   // toward the person's right: the viewer's left
  right.eye_left = right.eye_right = {0.45f, 0.0f};
  const model::RgbaImage a = render(ahead), l = render(left), r = render(right);
  ASSERT_GT(dark_centroid_x(a), 0.0f) << "no iris in the eye opening";
  EXPECT_LT(dark_centroid_x(l), dark_centroid_x(a) - 2.0f);
  EXPECT_GT(dark_centroid_x(r), dark_centroid_x(a) + 2.0f);
  // The skin around the opening, contour included, does not move at all.
  int changed = 0, compared = 0;
  for (int y = low.y - 12; y <= high.y + 12; ++y)
    for (int x = low.x - 12; x <= high.x + 12; ++x) {
      if (x >= low.x - 2 && x <= high.x + 2 && y >= low.y - 2 && y <= high.y + 2) continue;
      ++compared;
      changed += std::memcmp(a.at(x, y), l.at(x, y), 3) != 0;
    }
  EXPECT_EQ(changed, 0) << "of " << compared << " skin pixels around the eye";
}

TEST_F(ExpressiveRenderTest, AFullBlinkCoversTheEyeWithSkin) {
  glm::ivec2 low, high;
  eye_box(low, high);
  codec::FaceParams closed;
  closed.lid_left = closed.lid_right = 1.0f;
  const model::RgbaImage open = render({}), shut = render(closed);
  const glm::ivec2 centre = (low + high) / 2;
  const std::uint8_t* skin = open.at(centre.x, low.y - 10);  // the lid above the eye, open
  int skin_like = 0, total = 0;
  for (int y = centre.y - 1; y <= centre.y + 1; ++y)
    for (int x = low.x + 3; x <= high.x - 3; ++x) {
      const std::uint8_t* p = shut.at(x, y);
      ++total;
      skin_like += std::abs(p[0] - skin[0]) < 45 && std::abs(p[1] - skin[1]) < 45 && std::abs(p[2] - skin[2]) < 45 &&
                   p[0] > p[2];
    }
  EXPECT_GT(skin_like, total * 8 / 10) << skin_like << " of " << total << " pixels across the closed eye are skin";
}

// The closed-lid layer covers the eyes only: a blink during a broad smile
// and raised brows leaves the lips and brows as the smile has them (it once
// painted the whole rest-pose face over the expression). The closing lids
// stretch the skin up to the brows a little, which changes its shading by a
// few levels; a visible change is more than 8.
TEST_F(ExpressiveRenderTest, ABlinkLeavesLipsAndBrowsWhereTheyWere) {
  codec::FaceParams smile;
  smile.set_au(12, 1.0f);  // lip corners up
  smile.set_au(25, 0.6f);  // lips apart
  smile.set_au(1, 1.0f);   // inner brows up
  smile.set_au(2, 1.0f);   // outer brows up
  codec::FaceParams blinking = smile;
  blinking.lid_left = blinking.lid_right = 1.0f;
  const model::RgbaImage open = render(smile), shut = render(blinking);
  const auto changed_in = [&](glm::vec2 low, glm::vec2 high) {
    const glm::ivec2 a = pixel({low.x, high.y}), b = pixel({high.x, low.y});
    int changed = 0;
    for (int y = std::min(a.y, b.y); y <= std::max(a.y, b.y); ++y)
      for (int x = std::min(a.x, b.x); x <= std::max(a.x, b.x); ++x)
        for (int c = 0; c < 3; ++c) {
          if (std::abs(open.at(x, y)[c] - shut.at(x, y)[c]) > 8) {
            ++changed;
            break;
          }
        }
    return changed;
  };
  EXPECT_EQ(changed_in({-0.45f, -1.35f}, {0.45f, -0.85f}), 0) << "pixels of the mouth changed visibly";
  EXPECT_EQ(changed_in({-0.95f, 0.25f}, {0.95f, 0.7f}), 0) << "pixels of the brows changed visibly";
  EXPECT_GT(changed_in({0.3f, -0.08f}, {0.7f, 0.08f}), 20) << "the left eye closed";
}

TEST_F(ExpressiveRenderTest, CheekBlushReddensTheCheeksOnly) {
  codec::FaceParams blush;
  blush.blush[static_cast<std::size_t>(codec::ColourRegion::cheek_left)] = 1.0f;
  blush.blush[static_cast<std::size_t>(codec::ColourRegion::cheek_right)] = 1.0f;
  const model::RgbaImage before = render({}), after = render(blush);
  const auto red_over_green = [](const std::uint8_t* p) { return static_cast<float>(p[0]) / (1.0f + p[1]); };
  for (const glm::vec2 cheek : {glm::vec2(0.65f, -0.55f), glm::vec2(-0.65f, -0.55f)}) {
    const glm::ivec2 px = pixel(cheek);
    EXPECT_GT(red_over_green(after.at(px.x, px.y)), red_over_green(before.at(px.x, px.y)) * 1.15f) << cheek.x;
  }
  const glm::ivec2 bridge = pixel({0.0f, -0.15f});
  EXPECT_NEAR(red_over_green(after.at(bridge.x, bridge.y)), red_over_green(before.at(bridge.x, bridge.y)), 0.02f);
}

TEST_F(ExpressiveRenderTest, PallorDrainsTheWholeFace) {
  codec::FaceParams pale;
  pale.pallor = 1.0f;
  const model::RgbaImage before = render({}), after = render(pale);
  for (const glm::vec2 p : {glm::vec2(0.0f, 0.8f), glm::vec2(0.6f, -0.5f), glm::vec2(-0.6f, -0.5f), glm::vec2(0.0f, -1.6f)}) {
    const glm::ivec2 px = pixel(p);
    EXPECT_LT(saturation(after.at(px.x, px.y)), saturation(before.at(px.x, px.y)) * 0.7f) << p.x << "," << p.y;
  }
}

TEST(ContactSheet, HasNeutralEveryExpressionGazeBlinkBlushAndPallor) {
  const auto panels = sheet_panels();
  ASSERT_EQ(panels.size(), 17u);
  EXPECT_EQ(panels.front().name, "neutral");
  EXPECT_EQ(panels[1].name, "joy");
  EXPECT_EQ(panels[14].name, "pallor");
  EXPECT_EQ(panels.back().name, "turned 60");
  EXPECT_NEAR(panels.back().params.head_yaw_rad, 1.047f, 0.001f);
}

}  // namespace
}  // namespace fw::render
