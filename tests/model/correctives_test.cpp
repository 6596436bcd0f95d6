// The physics face's corrective components in the model: the asset carries
// them (version 7, `correctives`), avatars get them by motion cloning, and
// the reconstruction adds them at their weights.
#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "fw/model/avatar_model.hpp"
#include "fw/model/face_asset.hpp"
#include "fw/model/face_reconstruction.hpp"

namespace fw::model {
namespace {

// A component that moves every seventh vertex a little, the others not.
Morph sample_component(float scale) {
  Morph m;
  const auto& positions = generic_face().skin.positions;
  for (std::size_t v = 0; v < positions.size(); ++v)
    m.vertex_delta.push_back(v % 7 == 3 ? scale * glm::vec3(0.01f, -0.02f, 0.005f) : glm::vec3(0.0f));
  return m;
}

GenericFace face_with_correctives(std::size_t count) {
  GenericFace face = generic_face();
  face.correctives.clear();
  for (std::size_t k = 0; k < count; ++k) face.correctives.push_back(sample_component(1.0f + float(k)));
  return face;
}

std::string refusal(const GenericFace& face) {
  GenericFace parsed;
  std::string error;
  EXPECT_FALSE(parse_face_asset(serialize_face_asset(face), parsed, error));
  return error;
}

std::string refusal(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  GenericFace parsed;
  std::string error;
  EXPECT_FALSE(parse_face_asset(text, parsed, error));
  return error;
}

TEST(Correctives, RoundTripInTheAsset) {
  const GenericFace face = face_with_correctives(codec::kCorrectiveCount);
  const std::string text = serialize_face_asset(face);
  GenericFace parsed;
  std::string error;
  ASSERT_TRUE(parse_face_asset(text, parsed, error)) << error;
  ASSERT_EQ(parsed.correctives.size(), codec::kCorrectiveCount);
  for (std::size_t k = 0; k < parsed.correctives.size(); ++k)
    for (std::size_t v = 0; v < face.skin.positions.size(); ++v)  // 6 significant digits in the file
      EXPECT_LT(glm::length(parsed.correctives[k].vertex_delta[v] - face.correctives[k].vertex_delta[v]), 1e-7f) << k;
  EXPECT_EQ(serialize_face_asset(parsed), text);
}

TEST(Correctives, AFaceWithoutThemIsSound) {
  const GenericFace face = face_with_correctives(0);
  GenericFace parsed;
  std::string error;
  ASSERT_TRUE(parse_face_asset(serialize_face_asset(face), parsed, error)) << error;
  EXPECT_TRUE(parsed.correctives.empty());
}

TEST(Correctives, TheValidatorRefusesABadBasis) {
  GenericFace face = face_with_correctives(codec::kCorrectiveCount + 1);
  EXPECT_NE(refusal(face).find("at most 6 components"), std::string::npos) << refusal(face);
  EXPECT_FALSE(validate_generic_face(face).empty());

  face = face_with_correctives(2);
  face.correctives[1].vertex_delta[10] = glm::vec3(2.0f, 0.0f, 0.0f);
  EXPECT_NE(refusal(face).find("corrective component 1 moves vertex 10 implausibly far"), std::string::npos)
      << refusal(face);

  face = face_with_correctives(2);
  face.correctives[0].vertex_delta.assign(face.skin.positions.size(), glm::vec3(0.0f));
  EXPECT_NE(refusal(face).find("corrective component 0 moves no vertex"), std::string::npos) << refusal(face);

  face = face_with_correctives(1);
  face.correctives[0].uv_delta.assign(face.skin.positions.size(), glm::vec2(0.01f, 0.0f));
  const auto problems = validate_generic_face(face);
  ASSERT_FALSE(problems.empty());
  EXPECT_NE(problems.front().find("slides the texture"), std::string::npos) << problems.front();

  face = face_with_correctives(1);
  face.correctives[0].vertex_delta.pop_back();
  ASSERT_FALSE(validate_generic_face(face).empty());
  EXPECT_NE(validate_generic_face(face).front().find("does not cover every skin vertex"), std::string::npos);
}

TEST(Correctives, TheReaderNamesAMalformedComponent) {
  const std::string text = serialize_face_asset(face_with_correctives(2));
  std::string error = refusal(text, "{\"component\": 1", "{\"component\": 4");
  EXPECT_NE(error.find("correctives[1]: expected component 1"), std::string::npos) << error;
  error = refusal(text, "\"correctives\"", "\"correctives_renamed\"");
  EXPECT_NE(error.find("missing \"correctives\""), std::string::npos) << error;
  error = refusal(text, "{\"component\": 0, \"moves\": [\n      [3, ", "{\"component\": 0, \"moves\": [\n      [3, 1, ");
  EXPECT_NE(error.find("correctives[0].moves: expected [vertex, dx, dy, dz]"), std::string::npos) << error;
  error = refusal(text, "{\"component\": 0, \"moves\": [\n      [3, ", "{\"component\": 0, \"moves\": [\n      [99999, ");
  EXPECT_NE(error.find("correctives[0].moves: vertex index out of range"), std::string::npos) << error;
}

std::vector<glm::vec2> stretched(const glm::mat2& a) {
  std::vector<glm::vec2> xy;
  for (const glm::vec3& p : generic_face().skin.positions) xy.push_back(a * glm::vec2(p));
  return xy;
}

TEST(Correctives, AvatarsGetThemByMotionCloning) {
  const GenericFace face = face_with_correctives(3);
  const glm::mat2 stretch(1.2f, 0.0f, 0.0f, 0.8f);  // a wider, shorter face
  const AvatarModel avatar = make_avatar_model(face, stretched(stretch));
  ASSERT_EQ(avatar.correctives.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k)
    for (std::size_t v = 0; v < face.skin.positions.size(); ++v) {
      const glm::vec3 g = face.correctives[k].vertex_delta[v], c = avatar.correctives[k].vertex_delta[v];
      EXPECT_NEAR(c.x, 1.2f * g.x, 1e-5f);
      EXPECT_NEAR(c.y, 0.8f * g.y, 1e-5f);
      EXPECT_NEAR(c.z, std::sqrt(0.96f) * g.z, 1e-5f) << "depth by the local scale, as the action units";
    }
}

TEST(Correctives, TheReconstructionAddsThemAtTheirWeights) {
  const GenericFace face = face_with_correctives(2);
  const AvatarModel avatar = make_avatar_model(face, stretched(glm::mat2(1.1f)));
  codec::FaceParams params;
  params.au[codec::au_channel(12, codec::AuSide::left)] = 0.5f;
  const FaceShape plain = reconstruct_face(avatar, params);
  params.corrective = {0.5f, -1.0f, 0.9f, 0.9f, 0.9f, 0.9f};  // the face has two: the rest are not used
  const FaceShape corrected = reconstruct_face(avatar, params);
  for (std::size_t v = 0; v < plain.positions.size(); ++v) {
    const glm::vec3 expected =
        plain.positions[v] + 0.5f * avatar.correctives[0].vertex_delta[v] - avatar.correctives[1].vertex_delta[v];
    EXPECT_LT(glm::length(corrected.positions[v] - expected), 1e-6f) << v;
    EXPECT_EQ(corrected.uvs[v], plain.uvs[v]) << "a corrective slides no texture";
  }
  params.corrective = {3.0f, -7.0f, 0, 0, 0, 0};  // clamped to [-1,1]
  const FaceShape clamped = reconstruct_face(avatar, params);
  params.corrective = {1.0f, -1.0f, 0, 0, 0, 0};
  EXPECT_EQ(clamped.positions, reconstruct_face(avatar, params).positions);
  params.corrective = {std::nanf(""), 0, 0, 0, 0, 0};
  EXPECT_EQ(reconstruct_face(avatar, params).positions, plain.positions) << "a non-finite weight is 0";
}

}  // namespace
}  // namespace fw::model
