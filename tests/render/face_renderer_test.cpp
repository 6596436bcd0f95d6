#include "fw/render/face_renderer.hpp"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "fw/behavior/eye_head.hpp"
#include "fw/model/procedural_texture.hpp"
#include "pixel_count.hpp"
#include "polygon_inset.hpp"

namespace fw::render {
namespace {

using model::RgbaImage;

constexpr int kSize = 256;
const glm::vec3 kBackground{0.0f, 0.0f, 0.0f};

RgbaImage solid(int w, int h, glm::u8vec3 rgb) {
  RgbaImage image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = image.at(x, y);
      p[0] = rgb.r, p[1] = rgb.g, p[2] = rgb.b, p[3] = 255;
    }
  return image;
}

// The procedural skin recoloured to one colour, keeping its alpha holes.
RgbaImage flat_skin(glm::u8vec3 rgb, int size = 128) {
  RgbaImage skin = model::make_skin_texture(model::generic_face(), model::Appearance{}, size);
  for (int y = 0; y < skin.height; ++y)
    for (int x = 0; x < skin.width; ++x) {
      std::uint8_t* p = skin.at(x, y);
      p[0] = rgb.r, p[1] = rgb.g, p[2] = rgb.b;
    }
  return skin;
}

// A flat skin with a green mark at the nose tip, for tracking the nose in images.
RgbaImage skin_with_marked_nose() {
  RgbaImage skin = flat_skin({200, 150, 130}, 512);
  const auto& face = model::generic_face();
  const glm::vec2 tip = model::landmark_template()[model::landmarks::kNoseTip];
  for (int y = 0; y < skin.height; ++y)
    for (int x = 0; x < skin.width; ++x) {
      const glm::vec2 uv((x + 0.5f) / skin.width, 1.0f - (y + 0.5f) / skin.height);
      // Small, so that foreshortening of the mark on a turned nose cannot
      // move its centroid by more than a pixel or two.
      if (glm::length(face.texture_frame.to_model(uv) - tip) < 0.04f) {
        std::uint8_t* p = skin.at(x, y);
        p[0] = 0, p[1] = 255, p[2] = 0;
      }
    }
  return skin;
}

// Textures with no closed lid and no blood masks: those effects off.
FaceTextures plain(RgbaImage skin, RgbaImage eye, RgbaImage mouth) {
  FaceTextures t;
  t.skin = std::move(skin);
  t.eye = std::move(eye);
  t.mouth = std::move(mouth);
  return t;
}

bool is_background(const std::uint8_t* p) { return p[0] == 0 && p[1] == 0 && p[2] == 0; }

// Centroid of the pixels `pick` selects within [low, high); (-1,-1) if none.
template <typename Pick>
glm::vec2 centroid(const RgbaImage& image, Pick pick, glm::ivec2 low = glm::ivec2(0),
                   glm::ivec2 high = glm::ivec2(1 << 20)) {
  glm::vec2 sum(0.0f);
  int n = 0;
  high = glm::min(high, glm::ivec2(image.width, image.height));
  for (int y = std::max(0, low.y); y < high.y; ++y)
    for (int x = std::max(0, low.x); x < high.x; ++x)
      if (pick(image.at(x, y))) sum += glm::vec2(x + 0.5f, y + 0.5f), ++n;
  return n ? sum / static_cast<float>(n) : glm::vec2(-1.0f);
}

bool greenish(const std::uint8_t* p) { return p[1] > 120 && p[0] < 80 && p[2] < 80; }

class FaceRendererTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    std::string error;
    RendererOptions options;
    options.width = options.height = kSize;
    options.background = kBackground;
    renderer_ = FaceRenderer::create(options, error).release();
    ASSERT_NE(renderer_, nullptr) << error;
    const auto& face = model::generic_face();
    const auto look = model::Appearance{};
    natural_ = renderer_->add_face(face, plain(model::make_skin_texture(face, look, 256),
                                              model::make_eye_texture(face.eyes[0], look), model::make_mouth_texture()));
    marked_ = renderer_->add_face(face, plain(skin_with_marked_nose(), solid(8, 8, {0, 0, 255}), solid(8, 8, {40, 0, 0})));
    red_ = renderer_->add_face(face, plain(flat_skin({255, 0, 0}), solid(8, 8, {0, 0, 255}), solid(8, 8, {40, 0, 0})));
    blue_ = renderer_->add_face(face, plain(flat_skin({0, 0, 255}), solid(8, 8, {0, 255, 0}), solid(8, 8, {40, 0, 0})));
  }
  static void TearDownTestSuite() { delete renderer_; }

  static RgbaImage render_one(FaceId id, const HeadPose& pose = {}, glm::vec2 gaze = glm::vec2(0.0f)) {
    const FaceDraw draw{id, head_transform(pose), {gaze, gaze}};
    return renderer_->render({&draw, 1}, Camera::portrait(1.0f));
  }

  static inline FaceRenderer* renderer_ = nullptr;
  static inline FaceId natural_ = 0, marked_ = 0, red_ = 0, blue_ = 0;
};

TEST_F(FaceRendererTest, RunsOnASoftwareRenderer) {
  EXPECT_FALSE(renderer_->renderer_name().empty());
  EXPECT_EQ(renderer_->width(), kSize);
}

TEST_F(FaceRendererTest, FaceInTheCentreBackgroundInTheCorners) {
  const RgbaImage image = render_one(natural_);
  ASSERT_EQ(image.width, kSize);
  for (auto [x, y] : {std::pair{1, 1}, {kSize - 2, 1}, {1, kSize - 2}, {kSize - 2, kSize - 2}})
    EXPECT_TRUE(is_background(image.at(x, y))) << x << "," << y;
  int face_pixels = 0;
  for (int y = kSize / 4; y < 3 * kSize / 4; ++y)
    for (int x = kSize / 4; x < 3 * kSize / 4; ++x) face_pixels += !is_background(image.at(x, y));
  EXPECT_EQ(face_pixels, kSize * kSize / 4) << "the middle of the image is all face";
  // Lit skin, not black or white: the texture and the light both reached it.
  const std::uint8_t* cheek = image.at(kSize / 2 + kSize / 8, kSize / 2 + kSize / 16);
  EXPECT_GT(cheek[0], 100);
  EXPECT_GT(cheek[0], cheek[2]) << "skin is warmer than it is blue";
}

TEST_F(FaceRendererTest, NoseMarkLandsWhereTheCameraProjectsTheNoseTip) {
  const auto& face = model::generic_face();
  const glm::vec3 tip = face.skin.positions[face.landmark_vertices[model::landmarks::kNoseTip]];
  for (float yaw_deg : {0.0f, 30.0f, -30.0f}) {
    HeadPose pose;
    pose.yaw_rad = glm::radians(yaw_deg);
    const glm::vec2 seen = centroid(render_one(marked_, pose), greenish);
    const glm::vec3 expected =
        project_to_pixel(Camera::portrait(1.0f), glm::vec3(head_transform(pose) * glm::vec4(tip, 1.0f)), kSize, kSize);
    EXPECT_NEAR(seen.x, expected.x, 3.0f) << "yaw " << yaw_deg;
    EXPECT_NEAR(seen.y, expected.y, 3.0f) << "yaw " << yaw_deg;
  }
}

TEST_F(FaceRendererTest, YawTurnsTheNoseTowardTheFacesLeft) {
  HeadPose left, right;
  left.yaw_rad = glm::radians(30.0f);
  right.yaw_rad = glm::radians(-30.0f);
  const float centre = centroid(render_one(marked_), greenish).x;
  EXPECT_GT(centroid(render_one(marked_, left), greenish).x, centre + 10.0f) << "+yaw: viewer's right";
  EXPECT_LT(centroid(render_one(marked_, right), greenish).x, centre - 10.0f);
  HeadPose up;
  up.pitch_rad = glm::radians(20.0f);
  EXPECT_LT(centroid(render_one(marked_, up), greenish).y, centroid(render_one(marked_), greenish).y - 5.0f)
      << "+pitch: nose moves up the image";
}

void expect_blue_eyeballs_in_red_skin(const RgbaImage& image) {
  const auto& face = model::generic_face();
  for (std::size_t side = 0; side < 2; ++side) {
    const glm::vec3 eye = glm::vec3(face.eyes[side].centre.x, face.eyes[side].centre.y, 0.0f);
    // The eye opening's middle, on the skin surface in front of the eyeball.
    const glm::vec3 front(eye.x, eye.y, face.eyes[side].centre.z + face.eyes[side].radius);
    const glm::vec3 px = project_to_pixel(Camera::portrait(1.0f), front, kSize, kSize);
    const std::uint8_t* p = image.at(static_cast<int>(px.x), static_cast<int>(px.y));
    EXPECT_GT(p[2], 100) << "blue eyeball, side " << side;
    EXPECT_LT(p[0], 60) << "not red skin, side " << side;
  }
}

TEST_F(FaceRendererTest, EyeballShowsThroughTheEyeHole) { expect_blue_eyeballs_in_red_skin(render_one(red_)); }

// Without multisampling the holes are cut by an alpha test instead of
// coverage (another variant of the shader): the eyes still show.
TEST(FaceRendererWithoutMultisampling, EyeballShowsThroughTheEyeHole) {
  std::string error;
  RendererOptions options;
  options.width = options.height = kSize;
  options.samples = 0;
  options.background = kBackground;
  auto renderer = FaceRenderer::create(options, error);
  ASSERT_NE(renderer, nullptr) << error;
  const FaceId red = renderer->add_face(
      model::generic_face(), plain(flat_skin({255, 0, 0}), solid(8, 8, {0, 0, 255}), solid(8, 8, {40, 0, 0})));
  const FaceDraw draw{red, head_transform({}), {}};
  expect_blue_eyeballs_in_red_skin(renderer->render({&draw, 1}, Camera::portrait(1.0f)));
}

TEST_F(FaceRendererTest, NearerFaceHidesTheFartherWhateverTheDrawOrder) {
  const glm::mat4 near_place = glm::translate(glm::mat4(1.0f), glm::vec3(0.4f, 0.0f, 1.0f));
  const glm::mat4 far_place = glm::translate(glm::mat4(1.0f), glm::vec3(-0.4f, 0.0f, -1.0f));
  const FaceDraw near_red{red_, near_place, {}};
  const FaceDraw far_blue{blue_, far_place, {}};
  const Camera camera = Camera::portrait(1.0f);
  for (const auto& order : {std::array{near_red, far_blue}, std::array{far_blue, near_red}}) {
    const RgbaImage image = renderer_->render(order, camera);
    // The forehead of the near face, where both faces overlap on screen.
    const glm::vec3 px = project_to_pixel(camera, glm::vec3(near_place * glm::vec4(0.0f, 0.7f, 1.0f, 1.0f)), kSize, kSize);
    const std::uint8_t* p = image.at(static_cast<int>(px.x), static_cast<int>(px.y));
    EXPECT_GT(p[0], 100) << "red (near) face must win";
    EXPECT_LT(p[2], 40);
  }
}

TEST_F(FaceRendererTest, EyesTurnIndependentlyOfTheHead) {
  // Inside the left eye opening, the dark pupil and iris follow the gaze.
  const auto& face = model::generic_face();
  const Camera camera = Camera::portrait(1.0f);
  glm::vec2 low(1e9f), high(-1e9f);
  for (std::uint32_t v : face.eye_holes[static_cast<std::size_t>(model::Side::left)]) {
    const glm::vec3 px = project_to_pixel(camera, face.skin.positions[v], kSize, kSize);
    low = glm::min(low, glm::vec2(px));
    high = glm::max(high, glm::vec2(px));
  }
  const auto dark = [](const std::uint8_t* p) { return p[0] + p[1] + p[2] < 200; };
  const auto pupil_x = [&](glm::vec2 gaze) {
    return centroid(render_one(natural_, {}, gaze), dark, glm::ivec2(low), glm::ivec2(high) + 1).x;
  };
  const float ahead = pupil_x({0.0f, 0.0f});
  ASSERT_GT(ahead, low.x) << "no dark iris found in the eye opening";
  EXPECT_GT(pupil_x({0.4f, 0.0f}), ahead + 2.0f) << "looking toward the face's left";
  EXPECT_LT(pupil_x({-0.4f, 0.0f}), ahead - 2.0f) << "looking toward the face's right";
}

// Pixels whose centre lies inside `polygon` at least `inset` pixels from its edges.
std::vector<glm::ivec2> pixels_inside(const std::vector<glm::vec2>& polygon, float inset) {
  glm::vec2 low(1e9f), high(-1e9f);
  for (const glm::vec2& p : polygon) low = glm::min(low, p), high = glm::max(high, p);
  std::vector<glm::ivec2> inside;
  for (int y = static_cast<int>(low.y); y <= static_cast<int>(high.y); ++y)
    for (int x = static_cast<int>(low.x); x <= static_cast<int>(high.x); ++x) {
      if (test::inside_inset(polygon, {x + 0.5f, y + 0.5f}, inset)) inside.emplace_back(x, y);
    }
  return inside;
}

// However far the behaviour turns the eyes (EyeHeadController's oculomotor
// range aside, 34 degrees up or down), the eye holes of a face turned to the
// camera show eyeball, never the background behind the face.
TEST_F(FaceRendererTest, EyeHolesShowNoBackgroundAtTheLargestGaze) {
  const auto& face = model::generic_face();
  const Camera camera = Camera::portrait(1.0f);
  const float aside = behavior::EyeHeadController::kOculomotorRangeRad, up = 0.6f, thirty = 0.5236f;
  for (const glm::vec2 gaze : {glm::vec2(aside, 0.0f), glm::vec2(-aside, 0.0f), glm::vec2(thirty, 0.0f),
                               glm::vec2(-thirty, 0.0f), glm::vec2(0.0f, up), glm::vec2(0.0f, -up),
                               glm::vec2(aside, up), glm::vec2(-aside, -up)}) {
    const RgbaImage image = render_one(red_, {}, gaze);
    for (const auto& hole : face.eye_holes) {
      std::vector<glm::vec2> polygon;
      for (std::uint32_t v : hole) polygon.emplace_back(project_to_pixel(camera, face.skin.positions[v], kSize, kSize));
      const auto inside = pixels_inside(polygon, 1.0f);
      ASSERT_GT(inside.size(), 20u);
      int background = 0;
      for (const glm::ivec2 px : inside) background += is_background(image.at(px.x, px.y));
      EXPECT_EQ(background, 0) << "gaze " << gaze.x << "," << gaze.y;
    }
  }
}

// Only the rectangle the faces can reach is drawn by GL; the rest of the
// image is filled with the background as GL stores it. Either way it is
// one colour: a pixel a step or two from it would be a seam between them.
TEST(FaceRendererBackground, IsOneColourInsideAndOutsideWhatTheFacesReach) {
  std::string error;
  RendererOptions options;
  options.width = options.height = 128;
  options.background = {0.1f, 0.3f, 0.9f};
  auto renderer = FaceRenderer::create(options, error);
  ASSERT_NE(renderer, nullptr) << error;
  const auto& face = model::generic_face();
  const FaceId id = renderer->add_face(face, plain(model::make_skin_texture(face, model::Appearance{}, 128),
                                                   model::make_eye_texture(face.eyes[0], model::Appearance{}),
                                                   model::make_mouth_texture()));
  // Small and off to one side: most of the image lies outside its rectangle.
  const FaceDraw draw{id, glm::translate(glm::mat4(1.0f), glm::vec3(-1.5f, 1.0f, -6.0f)), {}};
  const RgbaImage image = renderer->render({&draw, 1}, Camera::portrait(1.0f));
  const std::uint8_t* corner = image.at(image.width - 1, image.height - 1);
  int background = 0, near_background = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.at(x, y);
      int distance = 0;
      for (int c = 0; c < 4; ++c) distance = std::max(distance, std::abs(p[c] - corner[c]));
      background += distance == 0;
      near_background += distance > 0 && distance <= 2;
    }
  EXPECT_GT(background, image.width * image.height / 2);
  EXPECT_LT(background, image.width * image.height) << "the face must be in the image";
  EXPECT_EQ(near_background, 0);
  EXPECT_EQ(corner[0], 26);
  EXPECT_EQ(corner[2], 230);
}

TEST(FaceRendererCreate, RejectsImpossibleSizes) {
  std::string error;
  RendererOptions options;
  options.width = 8;
  EXPECT_EQ(FaceRenderer::create(options, error), nullptr);
  EXPECT_NE(error.find("16..4096"), std::string::npos) << error;
}

}  // namespace
}  // namespace fw::render

namespace fw::render {
namespace {

// Background pixels the border cannot reach: holes inside the head.
int enclosed_background(const RgbaImage& image) {
  std::vector<std::uint8_t> reached(static_cast<std::size_t>(image.width * image.height), 0);
  std::vector<glm::ivec2> stack;
  for (int x = 0; x < image.width; ++x) stack.push_back({x, 0}), stack.push_back({x, image.height - 1});
  for (int y = 0; y < image.height; ++y) stack.push_back({0, y}), stack.push_back({image.width - 1, y});
  while (!stack.empty()) {
    const glm::ivec2 p = stack.back();
    stack.pop_back();
    if (p.x < 0 || p.y < 0 || p.x >= image.width || p.y >= image.height) continue;
    auto& seen = reached[static_cast<std::size_t>(p.y * image.width + p.x)];
    if (seen || !is_background(image.at(p.x, p.y))) continue;
    seen = 1;
    stack.insert(stack.end(), {{p.x + 1, p.y}, {p.x - 1, p.y}, {p.x, p.y + 1}, {p.x, p.y - 1}});
  }
  int holes = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (is_background(image.at(x, y)) && !reached[static_cast<std::size_t>(y * image.width + x)]) ++holes;
  return holes;
}

int head_pixels(const RgbaImage& image) {
  return fw::test::count_pixels(image, [](const std::uint8_t* p) { return !is_background(p); });
}

// Turned 60 degrees, the head shows its side, ear and back, not the edge of
// a mask: it covers about as much of the image as facing the camera, and
// its silhouette is solid (no background between the face and the shell).
// Seen from any side, above or below, no background shows through it
// either: the shell's far side is culled, so a triangle facing the wrong
// way or a visible opening would show as a hole of many pixels. A pixel or
// two is known: in exact profile, a slit where the jaw meets the neck, and
// steeply from below, the line between closed lips.
TEST_F(FaceRendererTest, ATurnedHeadIsAWholeHead) {
  const RgbaImage frontal = render_one(natural_);
  HeadPose pose;
  pose.yaw_rad = glm::radians(60.0f);
  const RgbaImage turned = render_one(natural_, pose);
  EXPECT_GT(head_pixels(turned), 0.8 * head_pixels(frontal));
  EXPECT_EQ(enclosed_background(frontal), 0);
  EXPECT_EQ(enclosed_background(turned), 0);
  for (const auto& [yaw, pitch] : {std::pair{90.0f, 0.0f}, std::pair{-90.0f, 0.0f}, std::pair{0.0f, 40.0f},
                                   std::pair{0.0f, -40.0f}, std::pair{-45.0f, 30.0f}, std::pair{70.0f, -30.0f}}) {
    HeadPose posed;
    posed.yaw_rad = glm::radians(yaw);
    posed.pitch_rad = glm::radians(pitch);
    EXPECT_LE(enclosed_background(render_one(natural_, posed)), 3) << "yaw " << yaw << ", pitch " << pitch;
  }
}

}  // namespace
}  // namespace fw::render
