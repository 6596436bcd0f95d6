// The eyes of a prepared avatar: the person's own iris and white, the
// procedural eye when the photo's eyes are too small, and a blink that
// closes over a lash line.
#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "fw/model/face_reconstruction.hpp"
#include "fw/model/procedural_texture.hpp"
#include "fw/photo/prepare_avatar.hpp"
#include "test_paths.hpp"
#include "photo_variants.hpp"
#include "rendered_avatar.hpp"

namespace fw::photo {
namespace {

class EyeFromPhotoTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    PrepError error;
    preparer_ = AvatarPreparer::create(std::nullopt, error).release();
    ASSERT_NE(preparer_, nullptr) << error.message;
  }
  static void TearDownTestSuite() { delete preparer_; }

  static PreparedAvatar prepare(const cv::Mat& photo) {
    PrepError error;
    auto avatar = preparer_->prepare(test::encode(photo), {}, error);
    EXPECT_TRUE(avatar.has_value()) << error.message;
    return avatar ? std::move(*avatar) : PreparedAvatar{};
  }

  static inline AvatarPreparer* preparer_ = nullptr;
};

cv::Mat decode(const model::PackageImage& image) {
  return cv::imdecode(cv::Mat(1, static_cast<int>(image.bytes.size()), CV_8UC1, const_cast<std::uint8_t*>(image.bytes.data())),
                      cv::IMREAD_COLOR);
}

// The mean colour (RGB) of the eye texture's iris: the ring between the
// pupil and the limbus, around the texture's centre.
cv::Vec3f iris_ring_mean(const cv::Mat& eye_bgr, const model::EyeLayer& eye) {
  const float iris_angle = std::asin(5.85f / model::kMillimetresPerUnit / eye.radius);
  const float limbus_px = 0.5f * iris_angle / eye.cap_angle_rad * static_cast<float>(eye_bgr.cols);
  cv::Mat ring = cv::Mat::zeros(eye_bgr.size(), CV_8UC1);
  const cv::Point centre(eye_bgr.cols / 2, eye_bgr.rows / 2);
  cv::circle(ring, centre, static_cast<int>(0.85f * limbus_px), cv::Scalar(255), cv::FILLED);
  cv::circle(ring, centre, static_cast<int>(0.45f * limbus_px), cv::Scalar(0), cv::FILLED);
  const cv::Scalar mean = cv::mean(eye_bgr, ring);
  return {static_cast<float>(mean[2]), static_cast<float>(mean[1]), static_cast<float>(mean[0])};
}

// Measured on the photo alone: within each landmark eye contour, the darker
// third of the pixels less the darkest tenth (pupil, lashes) is iris.
cv::Vec3f photo_iris_mean(const cv::Mat& photo, const std::array<glm::vec2, 68>& landmarks) {
  std::vector<cv::Vec3b> pixels;
  for (int begin : {36, 42}) {
    std::vector<cv::Point> polygon;
    for (int i = begin; i < begin + 6; ++i)
      polygon.emplace_back(static_cast<int>(landmarks[i].x), static_cast<int>(landmarks[i].y));
    cv::Mat mask = cv::Mat::zeros(photo.size(), CV_8UC1);
    cv::fillPoly(mask, std::vector<std::vector<cv::Point>>{polygon}, cv::Scalar(255));
    for (int y = 0; y < photo.rows; ++y)
      for (int x = 0; x < photo.cols; ++x)
        if (mask.at<std::uint8_t>(y, x)) pixels.push_back(photo.at<cv::Vec3b>(y, x));
  }
  const auto lum = [](const cv::Vec3b& c) { return 0.114f * c[0] + 0.587f * c[1] + 0.299f * c[2]; };
  std::sort(pixels.begin(), pixels.end(), [&](const cv::Vec3b& a, const cv::Vec3b& b) { return lum(a) < lum(b); });
  cv::Vec3f sum(0, 0, 0);
  const std::size_t begin = pixels.size() / 10, end = pixels.size() / 3;
  for (std::size_t i = begin; i < end; ++i) sum += cv::Vec3f(pixels[i][2], pixels[i][1], pixels[i][0]);
  return sum / static_cast<float>(end - begin);
}

void expect_iris_from_photo(const cv::Mat& photo, const PreparedAvatar& avatar) {
  const model::EyeLayer& eye = model::generic_face().eyes[0];
  const cv::Mat eye_texture = decode(avatar.package.eye);
  ASSERT_FALSE(eye_texture.empty());
  // Not the procedural eye of the same colour.
  model::Appearance look;
  look.iris = glm::vec3(avatar.package.iris_colour[0], avatar.package.iris_colour[1], avatar.package.iris_colour[2]) / 255.0f;
  cv::Mat procedural;
  cv::cvtColor(cv::Mat(eye_texture.rows, eye_texture.cols, CV_8UC4,
                       model::make_eye_texture(eye, look, eye_texture.cols).pixels.data()),
               procedural, cv::COLOR_RGBA2BGR);
  EXPECT_GT(cv::norm(eye_texture, procedural, cv::NORM_L1) / eye_texture.total(), 12.0) << "the procedural eye";
  // Its iris is the photo's.
  const cv::Vec3f texture_iris = iris_ring_mean(eye_texture, eye);
  const cv::Vec3f photo_iris = photo_iris_mean(photo, avatar.report.photo_landmarks);
  // The photo's measure takes in lashes and the lids' shade as well (behind
  // glasses, much of it), so it is darker than the iris alone, up to half
  // as bright: the hue must agree, the level only roughly.
  const auto chroma = [](cv::Vec3f c) { return c / std::max(1.0f, c[0] + c[1] + c[2]); };
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(chroma(texture_iris)[c], chroma(photo_iris)[c], 0.12f) << "channel " << c << " of the iris's hue";
  const float texture_level = texture_iris[0] + texture_iris[1] + texture_iris[2];
  const float photo_level = photo_iris[0] + photo_iris[1] + photo_iris[2];
  EXPECT_GT(texture_level, 0.7f * photo_level);
  EXPECT_LT(texture_level, 3.0f * photo_level);
}

TEST_F(EyeFromPhotoTest, TheEyeTextureHasTheAstronautsOwnIris) {
  const cv::Mat photo = test::load_astronaut();
  const PreparedAvatar avatar = prepare(photo);
  EXPECT_TRUE(avatar.report.warnings.empty());
  expect_iris_from_photo(photo, avatar);
}

// The astronaut's irises sit high in her eyes, their tops under the upper
// lids (0.016 and 0.034 units above the landmarks' middle): at rest the avatar's
// iris sits as high, not centred with white showing above it.
TEST_F(EyeFromPhotoTest, TheIrisSitsAsHighBehindTheLidsAsInThePhoto) {
  const PreparedAvatar avatar = prepare(test::load_astronaut());
  const cv::Mat eye_texture = decode(avatar.package.eye);
  ASSERT_FALSE(eye_texture.empty());
  cv::Mat gray;
  cv::cvtColor(eye_texture, gray, cv::COLOR_BGR2GRAY);
  // The iris's edges down the middle column: the first and the last rows
  // darker than halfway between the white beside the iris and the darkest.
  const cv::Mat column = gray.col(gray.cols / 2);
  double darkest = 0;
  cv::minMaxLoc(column, &darkest);
  const double white = gray.at<std::uint8_t>(gray.rows / 2, gray.cols / 8);
  int top = -1, bottom = -1;
  for (int row = 0; row < gray.rows; ++row)
    if (column.at<std::uint8_t>(row) < 0.5 * (white + darkest)) {
      if (top < 0) top = row;
      bottom = row;
    }
  ASSERT_GE(top, 0);
  const float rows_above_centre = 0.5f * static_cast<float>(gray.rows) - 0.5f * static_cast<float>(top + bottom + 1);
  // Her irises' rise turns the eyeball's texture by about 2.4 of its 96 rows;
  // the iris left centred reads 1 row (its pattern is not symmetric), moved
  // as in the photo 4.
  EXPECT_GT(rows_above_centre, 2.5f) << "the iris is centred on the eyeball, below where the photo shows it";
}

TEST_F(EyeFromPhotoTest, GlassesStayOutOfTheIris) {
  const cv::Mat photo = cv::imread(test::test_photo("grace_hopper.jpg"), cv::IMREAD_COLOR);
  ASSERT_FALSE(photo.empty());
  const PreparedAvatar avatar = prepare(photo);
  expect_iris_from_photo(photo, avatar);
}

TEST_F(EyeFromPhotoTest, EyesTooSmallInThePhotoGetTheProceduralEyeAndAWarning) {
  cv::Mat small;
  const cv::Mat photo = test::load_astronaut();
  cv::resize(photo, small, {}, 0.6, 0.6, cv::INTER_AREA);  // about 26 px between the eyes
  const PreparedAvatar avatar = prepare(small);
  ASSERT_FALSE(avatar.report.warnings.empty());
  EXPECT_NE(avatar.report.warnings.back().find("too small"), std::string::npos) << avatar.report.warnings.back();
  model::Appearance look;
  look.iris = glm::vec3(avatar.package.iris_colour[0], avatar.package.iris_colour[1], avatar.package.iris_colour[2]) / 255.0f;
  const cv::Mat eye_texture = decode(avatar.package.eye);
  cv::Mat procedural;
  cv::cvtColor(cv::Mat(eye_texture.rows, eye_texture.cols, CV_8UC4,
                       model::make_eye_texture(model::generic_face().eyes[0], look, eye_texture.cols).pixels.data()),
               procedural, cv::COLOR_RGBA2BGR);
  EXPECT_LT(cv::norm(eye_texture, procedural, cv::NORM_L1) / eye_texture.total(), 12.0) << "not the procedural eye";
}

// A full blink: where the lids meet, a dark lash line (darker than the lid
// skin above it); no eyeball showing anywhere (turning the eyes changes no
// pixel).
TEST_F(EyeFromPhotoTest, AFullBlinkShowsALashLineAndNoEye) {
  const PreparedAvatar avatar = prepare(test::load_astronaut());
  test::RenderedAvatar rendered(avatar.package, 512, {0.0f, 0.0f, 0.0f});
  codec::FaceParams params;
  params.lid_right = params.lid_left = 1.0f;
  const model::FaceShape shape = model::reconstruct_face(rendered.appearance.avatar, params);
  rendered.renderer->set_face_shape(rendered.id, shape.positions, shape.uvs);
  const model::RgbaImage image = rendered.draw(render::face_draw(rendered.id, params));
  params.eye_right = params.eye_left = {0.8f, 0.3f};
  EXPECT_EQ(rendered.draw(render::face_draw(rendered.id, params)).pixels, image.pixels) << "the eyeball shows";
  const auto& face = rendered.appearance.avatar.face;
  const auto pixel_of = [&](glm::vec3 p) {
    const glm::vec3 px = render::project_to_pixel(render::Camera::portrait(1.0f), p, 512, 512);
    return glm::ivec2(static_cast<int>(px.x), static_cast<int>(px.y));
  };
  const auto luminance = [&](glm::ivec2 px) {
    const std::uint8_t* p = image.at(px.x, px.y);
    return 0.299f * p[0] + 0.587f * p[1] + 0.114f * p[2];
  };
  for (const int lower : {41, 40, 47, 46}) {
    // The closed upper lid rests on the lower one: they meet at the lower contour.
    const glm::vec3 meet = shape.positions[face.landmark_vertices[static_cast<std::size_t>(lower)]];
    const glm::ivec2 at = pixel_of(meet);
    float darkest = 255.0f;
    for (int dy = -3; dy <= 3; ++dy) darkest = std::min(darkest, luminance(at + glm::ivec2(0, dy)));
    const float lid_above = luminance(pixel_of(meet + glm::vec3(0.0f, 0.06f, 0.0f)));
    EXPECT_LT(darkest, 0.7f * lid_above) << "landmark " << lower << ": no dark line where the lids meet";
  }
}

}  // namespace
}  // namespace fw::photo
