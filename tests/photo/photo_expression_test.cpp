// The photo's own expression, estimated and taken out: on landmarks made
// from known action units, and on a smiling photo whose avatar must be able
// to look sad, judged by dlib's landmarks on the renders.
#include "photo_expression.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "fw/model/expressions.hpp"
#include "fw/model/landmark_template.hpp"
#include "photo_variants.hpp"
#include "rendered_avatar.hpp"
#include "shared_preparer.hpp"
#include "template_landmarks.hpp"

namespace fw::photo {
namespace {

namespace lm = model::landmarks;

int channel(int au, codec::AuSide side) { return codec::au_channel(au, side); }

// The template's landmarks moved as the generic face's pictures move under
// the action units of `params`.
ModelLandmarks with_action_units(const codec::FaceParams& params) {
  const model::GenericFace& generic = model::generic_face();
  ModelLandmarks landmarks = template_landmarks();
  for (std::size_t c = 0; c < codec::kAuChannelCount; ++c)
    for (std::size_t i = 0; i < landmarks.size(); ++i) {
      const std::uint32_t v = generic.landmark_vertices[i];
      const model::Morph& morph = generic.action_units[c];
      landmarks[i] += params.au[c] * (glm::vec2(morph.vertex_delta[v]) - morph.uv_delta[v] * generic.texture_frame.size);
    }
  return landmarks;
}

float largest_gap(const ModelLandmarks& a, const ModelLandmarks& b) {
  float gap = 0;
  for (std::size_t i = 0; i < a.size(); ++i) gap = std::max(gap, glm::length(a[i] - b[i]));
  return gap;
}

TEST(PhotoExpression, ANeutralFaceHasNothingToTakeOut) {
  const PhotoExpression expression = estimate_expression(model::generic_face(), template_landmarks());
  for (std::size_t c = 0; c < codec::kAuChannelCount; ++c) EXPECT_LT(expression.au[c], 0.05f) << "channel " << c;
  EXPECT_LT(expression.largest_move, 0.01f);
}

TEST(PhotoExpression, AKnownSmileIsFoundAndTakenOut) {
  codec::FaceParams smile;
  for (const auto side : {codec::AuSide::left, codec::AuSide::right}) smile.au[channel(12, side)] = 1.0f;
  smile.au[channel(26, codec::AuSide::both)] = 0.5f;
  const PhotoExpression expression = estimate_expression(model::generic_face(), with_action_units(smile));
  for (const auto side : {codec::AuSide::left, codec::AuSide::right})
    EXPECT_NEAR(expression.au[channel(12, side)], 1.0f, 0.25f);
  EXPECT_NEAR(expression.au[channel(26, codec::AuSide::both)], 0.5f, 0.2f);
  EXPECT_LT(largest_gap(expression.neutral, template_landmarks()), 0.03f) << "back to the neutral face";
}

TEST(PhotoExpression, AWideOrLowMouthIsThePersonsOwnShapeNotAnExpression) {
  ModelLandmarks landmarks = template_landmarks();
  glm::vec2 centre(0.0f);
  for (int i = lm::kOuterLipBegin; i < lm::kInnerLipEnd; ++i) centre += landmarks[static_cast<std::size_t>(i)] / 20.0f;
  for (int i = lm::kOuterLipBegin; i < lm::kInnerLipEnd; ++i) {
    glm::vec2& p = landmarks[static_cast<std::size_t>(i)];
    p = {centre.x + 1.15f * (p.x - centre.x), p.y - 0.06f};
  }
  const PhotoExpression expression = estimate_expression(model::generic_face(), landmarks);
  for (std::size_t c = 0; c < codec::kAuChannelCount; ++c) EXPECT_LT(expression.au[c], 0.15f) << "channel " << c;
}

// --- a smiling photo, as its avatar renders -------------------------------

glm::vec2 centre_of(const PhotoLandmarks& l, int begin, int end) {
  glm::vec2 sum(0.0f);
  for (int i = begin; i < end; ++i) sum += l[static_cast<std::size_t>(i)] / float(end - begin);
  return sum;
}

float inter_ocular(const PhotoLandmarks& l) {
  return glm::length(centre_of(l, lm::kEyeLeftBegin, lm::kEyeLeftEnd) -
                     centre_of(l, lm::kEyeRightBegin, lm::kEyeRightEnd));
}

float corners_y(const PhotoLandmarks& l) {
  return 0.5f * (l[lm::kMouthCornerRight].y + l[lm::kMouthCornerLeft].y);
}

// How far the mouth corners sit above the middle of the lips, in
// inter-ocular distances (image rows run down): a smile is well above zero.
float corner_rise(const PhotoLandmarks& l) {
  const float middle = 0.5f * (l[62].y + l[66].y);
  return (middle - corners_y(l)) / inter_ocular(l);
}

// How far the mouth corners sit below the eyes, in inter-ocular distances.
float corner_depth(const PhotoLandmarks& l) {
  const float eyes = 0.5f * (centre_of(l, lm::kEyeLeftBegin, lm::kEyeLeftEnd).y +
                             centre_of(l, lm::kEyeRightBegin, lm::kEyeRightEnd).y);
  return (corners_y(l) - eyes) / inter_ocular(l);
}

PhotoLandmarks dlib_landmarks(const model::RgbaImage& render) {
  PrepError error;
  const auto seen = test::shared_preparer().prepare(test::encode(test::to_bgr(render)), {}, error);
  EXPECT_TRUE(seen.has_value()) << "dlib finds no face on the render: " << error.message;
  return seen ? seen->report.photo_landmarks : PhotoLandmarks{};
}

TEST(PhotoExpressionOnAPhoto, ASmilingPhotosAvatarCanLookSad) {
  PrepError error;
  const auto smiling = test::shared_preparer().prepare(test::encode(test::load_astronaut()), {}, error);
  ASSERT_TRUE(smiling.has_value()) << error.message;
  for (const auto side : {codec::AuSide::left, codec::AuSide::right})
    EXPECT_GT(smiling->report.photo_expression[static_cast<std::size_t>(channel(12, side))], 0.5f)
        << "the astronaut smiles broadly";
  const float photo_rise = corner_rise(smiling->report.photo_landmarks);

  test::RenderedAvatar avatar(smiling->package, 512, {0.5f, 0.5f, 0.5f});
  codec::FaceParams sad;
  model::apply_expression(model::Expression::sadness, 1.0f, sad);
  const PhotoLandmarks neutral = dlib_landmarks(avatar.draw(codec::FaceParams{}));
  const PhotoLandmarks sadness = dlib_landmarks(avatar.draw(sad));
  EXPECT_LT(corner_rise(neutral), photo_rise - 0.03f) << "the photo's smile is taken out of the avatar";
  EXPECT_GT(corner_depth(sadness), corner_depth(neutral) + 0.015f) << "sadness lowers the mouth corners";
}

}  // namespace
}  // namespace fw::photo
