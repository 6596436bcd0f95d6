#include "fw/model/face_asset.hpp"

#include <gtest/gtest.h>

namespace fw::model {
namespace {

std::string asset_error(const std::string& text) {
  GenericFace face;
  std::string error;
  EXPECT_FALSE(parse_face_asset(text, face, error));
  return error;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(FaceAsset, RoundTripsExactly) {
  const std::string text = serialize_face_asset(generic_face());
  GenericFace parsed;
  std::string error;
  ASSERT_TRUE(parse_face_asset(text, parsed, error)) << error;
  EXPECT_EQ(serialize_face_asset(parsed), text);
  EXPECT_EQ(parsed.skin.triangles, generic_face().skin.triangles);
  EXPECT_EQ(parsed.triangle_regions, generic_face().triangle_regions);
}

TEST(FaceAsset, RejectsWhatIsNotJson) {
  EXPECT_NE(asset_error("not json at all").find("not valid JSON"), std::string::npos);
  EXPECT_NE(asset_error("").find("not valid JSON"), std::string::npos);
}

TEST(FaceAsset, RejectsATruncatedFile) {
  const std::string text = serialize_face_asset(generic_face());
  for (std::size_t cut : {text.size() / 3, text.size() / 2, text.size() - 3})
    EXPECT_NE(asset_error(text.substr(0, cut)).find("not valid JSON"), std::string::npos) << cut;
}

TEST(FaceAsset, RejectsAnotherFormatOrVersion) {
  const std::string text = serialize_face_asset(generic_face());
  EXPECT_NE(asset_error(replaced(text, "facewire-generic-face", "something-else")).find("format"), std::string::npos);
  const std::string error =
      asset_error(replaced(text, "\"version\": " + std::to_string(kGenericFaceVersion), "\"version\": 99"));
  EXPECT_NE(error.find("version 99 is not supported"), std::string::npos) << error;
}

TEST(FaceAsset, NamesAMissingMember) {
  const std::string text = serialize_face_asset(generic_face());
  const std::string error = asset_error(replaced(text, "\"landmark_vertices\"", "\"landmarks_renamed\""));
  EXPECT_NE(error.find("missing \"landmark_vertices\""), std::string::npos) << error;
}

TEST(FaceAsset, RejectsUnknownRegion) {
  const std::string text = serialize_face_asset(generic_face());
  EXPECT_NE(asset_error(replaced(text, "\"forehead\"", "\"elbow\"")).find("unknown region"), std::string::npos);
}

TEST(FaceAsset, RejectsIndexOutOfRange) {
  GenericFace face = generic_face();
  face.skin.triangles[3].y = 100000;
  EXPECT_NE(asset_error(serialize_face_asset(face)).find("out of range"), std::string::npos);
}

TEST(FaceAsset, RejectsAFlippedTriangle) {
  GenericFace face = generic_face();
  std::swap(face.skin.triangles[10].y, face.skin.triangles[10].z);
  const std::string error = asset_error(serialize_face_asset(face));
  EXPECT_NE(error.find("flipped"), std::string::npos) << error;
}

TEST(FaceAsset, RejectsADegenerateTriangle) {
  GenericFace face = generic_face();
  const glm::uvec3 t = face.skin.triangles[20];
  face.skin.positions[t.z] = (face.skin.positions[t.x] + face.skin.positions[t.y]) * 0.5f;
  const auto problems = validate_generic_face(face);
  bool degenerate = false;
  for (const auto& p : problems) degenerate |= p.find("degenerate") != std::string::npos;
  EXPECT_TRUE(degenerate);
}

TEST(FaceAsset, RejectsAMissingHole) {
  // Closing the right eye hole with a triangle fan leaves three boundary loops.
  GenericFace face = generic_face();
  const auto& hole = face.eye_holes[0];
  for (std::size_t i = 1; i + 1 < hole.size(); ++i)
    face.skin.triangles.emplace_back(hole[0], hole[i + 1], hole[i]);
  face.triangle_regions.resize(face.skin.triangles.size(), FaceRegion::upper_lid_right);
  const std::string error = asset_error(serialize_face_asset(face));
  EXPECT_NE(error.find("boundary loops"), std::string::npos) << error;
}

TEST(FaceAsset, RejectsTriangleWithoutRegion) {
  GenericFace face = generic_face();
  face.triangle_regions.pop_back();
  EXPECT_NE(asset_error(serialize_face_asset(face)).find("triangle regions"), std::string::npos);
}

TEST(FaceAsset, RejectsSharedLandmarkVertex) {
  GenericFace face = generic_face();
  face.landmark_vertices[5] = face.landmark_vertices[6];
  EXPECT_NE(asset_error(serialize_face_asset(face)).find("share one vertex"), std::string::npos);
}

}  // namespace
}  // namespace fw::model
