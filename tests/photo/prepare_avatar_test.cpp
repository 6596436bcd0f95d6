// Photo to avatar on the astronaut portrait and variants of it made in code,
// and every kind of bad photo a person might send.
#include "fw/photo/prepare_avatar.hpp"

#include <cstdlib>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "fw/model/face_asset.hpp"
#include "fw/model/fitted_face.hpp"
#include "fw/model/landmark_template.hpp"
#include "fw/render/avatar_appearance.hpp"
#include "fw/render/face_renderer.hpp"
#include "rendered_avatar.hpp"
#include "shared_preparer.hpp"
#include "photo_variants.hpp"

namespace fw::photo {
namespace {

namespace lm = model::landmarks;

class PrepareAvatarTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    preparer_ = &test::shared_preparer();
    original_ = new cv::Mat(test::load_astronaut());
    ASSERT_FALSE(original_->empty()) << "missing test photo " << test::astronaut_path();
  }
  static void TearDownTestSuite() { delete original_; }

  static std::optional<PreparedAvatar> prepare(const std::vector<std::uint8_t>& bytes, PrepError& error,
                                               PrepOptions options = {}) {
    return preparer_->prepare(bytes, options, error);
  }
  // Expects refusal with `code` and a message containing `says`.
  static void expect_refused(const std::vector<std::uint8_t>& bytes, PrepErrorCode code, const std::string& says) {
    PrepError error;
    EXPECT_FALSE(prepare(bytes, error).has_value());
    EXPECT_EQ(error.code, code) << error.message;
    EXPECT_NE(error.message.find(says), std::string::npos) << error.message;
  }
  static float inter_ocular(const std::array<glm::vec2, 68>& l) {
    glm::vec2 right(0.0f), left(0.0f);
    for (int i = 0; i < 6; ++i) right += l[36 + i] / 6.0f, left += l[42 + i] / 6.0f;
    return glm::length(left - right);
  }

  // Each variant is accepted, and its landmarks agree with the original's,
  // mapped through the variant's transform, within 5 % of the inter-ocular
  // distance.
  static void expect_same_landmarks(const std::vector<test::PhotoVariant>& variants);

  static inline AvatarPreparer* preparer_ = nullptr;
  static inline cv::Mat* original_ = nullptr;
};

TEST_F(PrepareAvatarTest, AstronautMakesASmallSoundPackage) {
  PrepError error;
  const auto avatar = prepare(test::encode(*original_), error);
  ASSERT_TRUE(avatar.has_value()) << error.message;
  EXPECT_EQ(avatar->report.faces_found, 1);
  EXPECT_TRUE(avatar->report.warnings.empty());
  const auto bytes = model::serialize_avatar_package(avatar->package);
  EXPECT_LE(bytes.size(), 24u * 1024) << "the package must stay small for slow links";
  model::AvatarPackage parsed;
  std::string parse_error;
  ASSERT_TRUE(model::parse_avatar_package(bytes, parsed, parse_error)) << parse_error;
  EXPECT_TRUE(model::validate_generic_face(model::fit_generic_face(model::generic_face(), parsed.fitted_vertices)).empty());
  // Eyes at the eyes: alignment puts the eye centres at (+-0.5, 0).
  glm::vec2 right(0.0f), left(0.0f);
  for (int i = 0; i < 6; ++i) right += parsed.landmarks[36 + i] / 6.0f, left += parsed.landmarks[42 + i] / 6.0f;
  EXPECT_NEAR(right.x, -0.5f, 1e-3f);
  EXPECT_NEAR(left.x, 0.5f, 1e-3f);
  EXPECT_NEAR(right.y, 0.0f, 1e-3f);
  // Skin tone and iris are plausible colours of her photo: warm skin, darker iris.
  EXPECT_GT(parsed.skin_tone[0], parsed.skin_tone[2]);
  EXPECT_LT(parsed.iris_colour[0] + parsed.iris_colour[1] + parsed.iris_colour[2],
            parsed.skin_tone[0] + parsed.skin_tone[1] + parsed.skin_tone[2]);
}

TEST_F(PrepareAvatarTest, TextureHasHolesExactlyAtTheEyes) {
  PrepError error;
  const auto avatar = prepare(test::encode(*original_), error);
  ASSERT_TRUE(avatar.has_value()) << error.message;
  const model::RgbaImage& texture = avatar->report.face_texture;
  const model::TextureFrame& frame = model::generic_face().texture_frame;
  const auto alpha_at = [&](glm::vec2 p) {
    const glm::vec2 uv = frame.to_uv(p);
    return texture.at(static_cast<int>(uv.x * texture.width), static_cast<int>((1 - uv.y) * texture.height))[3];
  };
  EXPECT_EQ(alpha_at({-0.5f, 0.0f}), 0);
  EXPECT_EQ(alpha_at({0.5f, 0.0f}), 0);
  EXPECT_EQ(alpha_at({0.0f, 0.0f}), 255) << "between the eyes";
  EXPECT_EQ(alpha_at({0.0f, -1.0f}), 255) << "the mouth is skin in the face texture";
}

TEST_F(PrepareAvatarTest, VariantsFindTheSameLandmarks) { expect_same_landmarks(test::standard_variants(*original_)); }

// A photo stored sideways or upside down, or a head rolled far over, is
// accepted, and its landmarks, mapped back, are the upright photo's.
TEST_F(PrepareAvatarTest, AnyRollIsAcceptedWithTheSameLandmarks) {
  expect_same_landmarks(test::roll_variants(*original_));
}

void PrepareAvatarTest::expect_same_landmarks(const std::vector<test::PhotoVariant>& variants) {
  PrepError error;
  const auto reference = prepare(test::encode(*original_), error);
  ASSERT_TRUE(reference.has_value()) << error.message;
  const auto& original_landmarks = reference->report.photo_landmarks;
  for (const test::PhotoVariant& variant : variants) {
    SCOPED_TRACE(variant.name);
    const auto avatar = prepare(test::encode(variant.image), error);
    ASSERT_TRUE(avatar.has_value()) << error.message;
    const auto& found = avatar->report.photo_landmarks;
    std::array<glm::vec2, 68> expected{};
    for (int i = 0; i < 68; ++i) {
      const int source = variant.mirrored ? model::mirrored_landmark(i) : i;
      expected[static_cast<std::size_t>(i)] = variant.transform(original_landmarks[static_cast<std::size_t>(source)]);
    }
    const float tolerance = 0.05f * inter_ocular(expected);
    float worst = 0;
    int worst_index = 0;
    for (std::size_t i = 0; i < 68; ++i) {
      const float e = glm::length(found[i] - expected[i]);
      if (e > worst) worst = e, worst_index = static_cast<int>(i);
    }
    EXPECT_LE(worst, tolerance) << "landmark " << worst_index << " is " << worst << " px off (5% IOD = " << tolerance << ")";
  }
}

TEST_F(PrepareAvatarTest, HonoursExifOrientation) {
  // The photo stored turned a quarter to the left, with EXIF saying
  // "rotate 90 degrees clockwise to view" (orientation 6).
  cv::Mat stored;
  cv::rotate(*original_, stored, cv::ROTATE_90_COUNTERCLOCKWISE);
  std::vector<std::uint8_t> jpeg = test::encode(stored, ".jpg");
  const std::uint8_t exif[] = {0xFF, 0xE1, 0x00, 0x22, 'E', 'x', 'i', 'f', 0, 0, 'I', 'I', 0x2A, 0x00, 0x08, 0x00, 0x00, 0x00,
                               0x01, 0x00, 0x12, 0x01, 0x03, 0x00, 0x01, 0x00, 0x00, 0x00, 0x06, 0x00, 0x00, 0x00,
                               0x00, 0x00, 0x00, 0x00};
  jpeg.insert(jpeg.begin() + 2, std::begin(exif), std::end(exif));
  PrepError error;
  const auto avatar = prepare(jpeg, error);
  ASSERT_TRUE(avatar.has_value()) << error.message;
  EXPECT_EQ(avatar->report.photo_width, original_->cols);
  EXPECT_EQ(avatar->report.photo_height, original_->rows);
  EXPECT_LT(std::abs(avatar->report.roll_deg), 10.0f) << "upright after applying the orientation";
}

TEST_F(PrepareAvatarTest, SeveralFacesTakeTheLargestOrTheOneChosen) {
  // Two heads cut from the portrait (not its badges and flag), one smaller.
  const cv::Mat head = (*original_)(cv::Rect(110, 0, 290, 330));
  cv::Mat canvas(900, 1400, CV_8UC3, cv::Scalar(120, 120, 120));
  cv::Mat small;
  cv::resize(head, small, cv::Size(), 0.7, 0.7, cv::INTER_AREA);
  head.copyTo(canvas(cv::Rect(50, 50, head.cols, head.rows)));
  small.copyTo(canvas(cv::Rect(900, 300, small.cols, small.rows)));
  PrepError error;
  const auto largest = prepare(test::encode(canvas), error);
  ASSERT_TRUE(largest.has_value()) << error.message;
  EXPECT_EQ(largest->report.faces_found, 2);
  ASSERT_EQ(largest->report.warnings.size(), 1u);
  EXPECT_NE(largest->report.warnings[0].find("found 2 faces; using the largest"), std::string::npos);
  EXPECT_LT(largest->report.photo_landmarks[30].x, 600.0f) << "the full-size face is on the left";

  PrepOptions second;
  second.face_index = 1;
  const auto other = prepare(test::encode(canvas), error, second);
  ASSERT_TRUE(other.has_value()) << error.message;
  EXPECT_GT(other->report.photo_landmarks[30].x, 900.0f);

  second.face_index = 2;
  EXPECT_FALSE(prepare(test::encode(canvas), error, second).has_value());
  EXPECT_EQ(error.code, PrepErrorCode::face_index_out_of_range);
  EXPECT_NE(error.message.find("0..1"), std::string::npos) << error.message;
}

TEST_F(PrepareAvatarTest, RefusesWhatIsNotAnImage) {
  const std::string text = "Dear facewire, here is my photo.";
  expect_refused({text.begin(), text.end()}, PrepErrorCode::not_an_image, "not an image");
  expect_refused({}, PrepErrorCode::not_an_image, "not an image");
}

TEST_F(PrepareAvatarTest, TheCheckWithoutTheModelRefusesWhatPrepareRefusesFromTheHeader) {
  PrepError error;
  const std::string text = "not a png";
  EXPECT_FALSE(AvatarPreparer::check_photo(std::vector<std::uint8_t>(text.begin(), text.end()), error));
  EXPECT_EQ(error.code, PrepErrorCode::not_an_image);
  std::vector<std::uint8_t> big = test::encode(*original_);
  big.resize(10 * 1000 * 1000 + 1, 0);
  EXPECT_FALSE(AvatarPreparer::check_photo(big, error));
  EXPECT_EQ(error.code, PrepErrorCode::too_many_bytes);
  EXPECT_TRUE(AvatarPreparer::check_photo(test::encode(*original_), error)) << error.message;
}

TEST_F(PrepareAvatarTest, NamesUnsupportedFormats) {
  expect_refused(test::encode(*original_, ".bmp"), PrepErrorCode::unsupported_format, "BMP image; facewire reads JPEG, PNG and WebP");
  const std::string gif = "GIF89a\x01\x00\x01\x00\x00\x00\x00;";
  expect_refused({gif.begin(), gif.end()}, PrepErrorCode::unsupported_format, "GIF");
}

TEST_F(PrepareAvatarTest, RefusesTooManyBytes) {
  std::vector<std::uint8_t> big = test::encode(*original_);
  big.resize(10 * 1000 * 1000 + 1, 0);
  expect_refused(big, PrepErrorCode::too_many_bytes, "at most 10 MB");
}

TEST_F(PrepareAvatarTest, RefusesTooManyPixelsFromTheHeaderAlone) {
  // A tiny PNG whose header claims 8000 x 6000 pixels: refused before decoding.
  cv::Mat wide(1, 8000, CV_8UC1, cv::Scalar(0));
  std::vector<std::uint8_t> png = test::encode(wide);
  // IHDR height is bytes 20..23 (big-endian).
  png[20] = 0, png[21] = 0, png[22] = 0x17, png[23] = 0x70;  // 6000
  expect_refused(png, PrepErrorCode::too_many_pixels, "8000x6000 pixels; at most 40 megapixels");
}

TEST_F(PrepareAvatarTest, RefusesTruncatedFiles) {
  std::vector<std::uint8_t> png = test::encode(*original_);
  png.resize(png.size() / 2);
  expect_refused(png, PrepErrorCode::truncated, "truncated");
  std::vector<std::uint8_t> jpeg = test::encode(*original_, ".jpg");
  jpeg.resize(jpeg.size() * 2 / 3);
  expect_refused(jpeg, PrepErrorCode::truncated, "truncated");
}

TEST_F(PrepareAvatarTest, NoFaceSuggestsWhatWorks) {
  cv::Mat landscape(600, 800, CV_8UC3);
  cv::randu(landscape, cv::Scalar(0, 0, 0), cv::Scalar(255, 255, 255));
  cv::GaussianBlur(landscape, landscape, cv::Size(31, 31), 8);
  expect_refused(test::encode(landscape), PrepErrorCode::no_face, "take one facing the camera in good light");
}

TEST_F(PrepareAvatarTest, RefusesATinyFace) {
  cv::Mat tiny;
  cv::resize(*original_, tiny, cv::Size(), 0.3, 0.3, cv::INTER_AREA);
  expect_refused(test::encode(tiny), PrepErrorCode::face_too_small, "px wide; at least 40 px is needed");
}

TEST_F(PrepareAvatarTest, RefusesAFaceCutOffByTheEdge) {
  // Keep only the photo's left part, up to the middle of her face.
  const cv::Mat cut = (*original_)(cv::Rect(0, 0, 232, 400)).clone();
  PrepError error;
  EXPECT_FALSE(prepare(test::encode(cut), error).has_value());
  // Either the detector still sees half a face (cut off) or it sees none.
  EXPECT_TRUE(error.code == PrepErrorCode::face_cut_off || error.code == PrepErrorCode::no_face) << error.message;
  if (error.code == PrepErrorCode::face_cut_off) {
    EXPECT_NE(error.message.find("cut off by the edge"), std::string::npos);
  }
}

// A turned head: the astronaut's own avatar, rendered turned.
cv::Mat render_turned(const model::AvatarPackage& package, float yaw_deg) {
  test::RenderedAvatar avatar(package, 512, {0.5f, 0.5f, 0.5f});
  render::HeadPose pose;
  pose.yaw_rad = glm::radians(yaw_deg);
  return test::to_bgr(avatar.draw(render::FaceDraw{avatar.id, render::head_transform(pose), {}}));
}

// The head cut from its background: the astronaut's head, hair and neck cut
// out with a generous ellipse onto a uniform saturated green. Her rendered
// head's outline, frontal and turned, has no green in it.
TEST_F(PrepareAvatarTest, NoBackgroundAtTheOutline) {
  PrepError error;
  const auto reference = prepare(test::encode(*original_), error);
  ASSERT_TRUE(reference.has_value()) << error.message;
  const auto& l = reference->report.photo_landmarks;
  glm::vec2 right(0.0f), left(0.0f);
  for (int i = 0; i < 6; ++i) right += l[36 + i] / 6.0f, left += l[42 + i] / 6.0f;
  const float iod = glm::length(left - right);
  const glm::vec2 centre = 0.5f * (left + right) + glm::vec2(0.0f, 0.35f * iod);
  cv::Mat mask = cv::Mat::zeros(original_->size(), CV_8U);
  cv::ellipse(mask, cv::Point(static_cast<int>(centre.x), static_cast<int>(centre.y)),
              cv::Size(static_cast<int>(1.45f * iod), static_cast<int>(2.2f * iod)), 0, 0, 360, cv::Scalar(255), -1);
  cv::Mat on_green(original_->size(), CV_8UC3, cv::Scalar(0, 210, 0));
  original_->copyTo(on_green, mask);
  const auto avatar = prepare(test::encode(on_green), error);
  ASSERT_TRUE(avatar.has_value()) << error.message;

  for (const float yaw : {0.0f, 45.0f}) {
    SCOPED_TRACE("yaw " + std::to_string(yaw));
    const cv::Mat image = render_turned(avatar->package, yaw);
    // The outline: head pixels next to the grey background (as the
    // renderer writes it: its corner).
    const cv::Vec3b background = image.at<cv::Vec3b>(0, 0);
    const auto is_background = [&](int x, int y) { return image.at<cv::Vec3b>(y, x) == background; };
    int outline = 0, green = 0;
    for (int y = 1; y + 1 < image.rows; ++y)
      for (int x = 1; x + 1 < image.cols; ++x) {
        if (is_background(x, y)) continue;
        if (!is_background(x - 1, y) && !is_background(x + 1, y) && !is_background(x, y - 1) && !is_background(x, y + 1))
          continue;
        ++outline;
        const cv::Vec3b c = image.at<cv::Vec3b>(y, x);  // BGR
        if (c[1] > c[2] + 40 && c[1] > c[0] + 40) ++green;
      }
    EXPECT_GT(outline, 500) << "a head's outline";
    EXPECT_EQ(green, 0) << "of " << outline << " outline pixels, " << green << " are the background's green";
  }
}

TEST_F(PrepareAvatarTest, AcceptsAHeadTurned30DegreesAndRefusesOneTurnedAway) {
  PrepError error;
  const auto reference = prepare(test::encode(*original_), error);
  ASSERT_TRUE(reference.has_value()) << error.message;
  // Facing the camera, and turned 30 degrees, the rendered avatar is accepted...
  EXPECT_TRUE(prepare(test::encode(render_turned(reference->package, 0.0f)), error).has_value()) << error.message;
  const auto thirty = prepare(test::encode(render_turned(reference->package, 30.0f)), error);
  EXPECT_TRUE(thirty.has_value()) << error.message;
  // ...turned far away, it is not: the detector no longer sees a face there
  // (pose_checks_test covers the estimate's own limit of 35 degrees).
  const auto turned = prepare(test::encode(render_turned(reference->package, 60.0f)), error);
  EXPECT_FALSE(turned.has_value()) << "accepted with an estimated turn of " << turned->report.yaw_deg << " degrees";
  EXPECT_TRUE(error.code == PrepErrorCode::head_turned || error.code == PrepErrorCode::no_face) << error.message;
  EXPECT_NE(error.message.find("facing the camera"), std::string::npos) << error.message;
}

TEST_F(PrepareAvatarTest, RefusesBadOptions) {
  PrepError error;
  PrepOptions options;
  options.quality = 0;
  EXPECT_FALSE(prepare(test::encode(*original_), error, options).has_value());
  EXPECT_EQ(error.code, PrepErrorCode::bad_option);
}

TEST(AvatarPreparerCreate, SaysWhereTheModelShouldBe) {
  PrepError error;
  EXPECT_EQ(AvatarPreparer::create(std::filesystem::path("/no/model.dat"), error), nullptr);
  EXPECT_EQ(error.code, PrepErrorCode::model_missing);
  EXPECT_NE(error.message.find("/no/model.dat"), std::string::npos);
  EXPECT_NE(error.message.find("libdlib-data"), std::string::npos);
}

}  // namespace
}  // namespace fw::photo

namespace fw::photo {
namespace {

TEST_F(PrepareAvatarTest, WithoutAnEyeLayerTheEyesAreThePhotosAndStayPut) {
  PrepOptions options;
  options.eye_layer = false;
  PrepError error;
  const auto avatar = prepare(test::encode(*original_), error, options);
  ASSERT_TRUE(avatar.has_value()) << error.message;
  EXPECT_TRUE(avatar->package.eye.bytes.empty());
  model::AvatarPackage parsed;
  std::string parse_error;
  ASSERT_TRUE(model::parse_avatar_package(model::serialize_avatar_package(avatar->package), parsed, parse_error))
      << parse_error;
  test::RenderedAvatar rendered(parsed, 256, {0, 0, 0});
  const auto draw_looking = [&](float yaw) {
    render::FaceDraw draw{rendered.id, glm::mat4(1.0f), {}};
    draw.eye_yaw_pitch_rad = {glm::vec2(yaw, 0.0f), glm::vec2(yaw, 0.0f)};
    return rendered.draw(draw);
  };
  const model::RgbaImage left = draw_looking(-0.4f), right = draw_looking(0.4f);
  EXPECT_EQ(left.pixels, right.pixels) << "pupils fixed: gaze changes nothing";
  // The eye opening shows the photo (dark iris included), never the black background.
  const model::EyeLayer& eye = rendered.appearance.avatar.face.eyes[1];
  const glm::vec3 px = render::project_to_pixel(render::Camera::portrait(1.0f),
                                                eye.centre + glm::vec3(0, 0, eye.radius), 256, 256);
  for (int dx = -4; dx <= 4; dx += 2) {
    const std::uint8_t* p = left.at(static_cast<int>(px.x) + dx, static_cast<int>(px.y));
    EXPECT_GT(p[0] + p[1] + p[2], 0) << dx;
  }
}

}  // namespace
}  // namespace fw::photo
