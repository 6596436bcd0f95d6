// RedefinedFaces: an avatar's face drawn with the units its person
// redefined, whichever of package and units comes first, again on a new
// package, and with the shipped units after a restore.
#include "redefined_faces.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "fw/model/face_reconstruction.hpp"
#include "fw/model/motion_cloning.hpp"
#include "fw/model/unit_morphs.hpp"

namespace fw::client {
namespace {

// AU 12's left side (a redefinition is split over the unit's two sides).
const std::size_t kAu12 = static_cast<std::size_t>(codec::au_channel(12, codec::AuSide::left));

// A fitted face (wider than the generic one), so that a unit is carried
// onto the fit rather than copied.
RedefinedFaces::Face wide_face() {
  auto face = std::make_shared<render::AvatarAppearance>(render::generic_appearance({}));
  std::vector<glm::vec2> xy;
  for (const glm::vec3& p : model::generic_face().skin.positions) xy.emplace_back(1.1f * p.x, 0.95f * p.y);
  face->avatar = model::make_avatar_model(model::generic_face(), xy);
  return face;
}

// The lip corners' side of the face pulled down 0.2 units: nothing like a smile.
codec::UnitMorphs pull_down(std::uint32_t avatar, std::uint32_t version) {
  const auto& generic = model::generic_face();
  model::Morph morph;
  morph.vertex_delta.assign(generic.skin.positions.size(), glm::vec3(0.0f));
  morph.uv_delta.assign(morph.vertex_delta.size(), glm::vec2(0.0f));
  for (std::size_t v = 0; v < morph.vertex_delta.size(); ++v)
    if (generic.skin.positions[v].y < 0.0f) morph.vertex_delta[v] = glm::vec3(0.0f, -0.2f, 0.0f);
  codec::UnitMorphs message;
  message.avatar = avatar;
  message.version = version;
  message.units.push_back(model::unit_morph_message(kAu12, morph));
  return message;
}

codec::UnitMorphs restore(std::uint32_t avatar, std::uint32_t version) {
  codec::UnitMorphs message;
  message.avatar = avatar;
  message.version = version;
  return message;
}

// The skin with AU 12 at full intensity.
std::vector<glm::vec3> smiling(const RedefinedFaces::Face& face) {
  codec::FaceParams params;
  params.au[kAu12] = 1.0f;
  return model::reconstruct_face(face->avatar, params).positions;
}

float largest_difference(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
  float largest = 0;
  for (std::size_t v = 0; v < std::min(a.size(), b.size()); ++v) largest = std::max(largest, glm::length(a[v] - b[v]));
  return largest;
}

TEST(RedefinedFaces, UnitsThatComeFirstWaitForThePackageAndAreCarriedOntoItsFit) {
  RedefinedFaces faces;
  std::string error;
  EXPECT_EQ(faces.units_arrived(pull_down(7, 1), error), nullptr) << "no package yet: nothing to draw";
  const auto shipped = wide_face();
  const auto drawn = faces.package_arrived(7, shipped, error);
  ASSERT_TRUE(drawn);
  EXPECT_EQ(error, "");
  EXPECT_NE(drawn, shipped) << "the shipped face is left as it is";
  EXPECT_GT(largest_difference(smiling(drawn), smiling(shipped)), 0.1f);
  // Exactly the model's carrying: the wire's morph cloned onto the fit.
  model::AvatarModel expected = shipped->avatar;
  std::string ignored;
  model::set_unit_morphs(expected, model::generic_face(),
                         *model::unit_morph_set(pull_down(7, 1), model::generic_face().skin.positions.size(), ignored));
  EXPECT_EQ(drawn->avatar.morphs[kAu12].vertex_delta, expected.morphs[kAu12].vertex_delta);
  // Other units are the shipped ones.
  const std::size_t au1 = static_cast<std::size_t>(codec::au_channel(1, codec::AuSide::left));
  EXPECT_EQ(drawn->avatar.morphs[au1].vertex_delta, shipped->avatar.morphs[au1].vertex_delta);
}

TEST(RedefinedFaces, ANewPackageGetsTheUnitsAgainAndARestoreBringsBackTheShippedUnits) {
  RedefinedFaces faces;
  std::string error;
  const auto preview = wide_face();
  EXPECT_EQ(faces.package_arrived(3, preview, error), preview) << "no units: the package's own face";
  const auto redefined = faces.units_arrived(pull_down(3, 1), error);
  ASSERT_TRUE(redefined);
  EXPECT_GT(largest_difference(smiling(redefined), smiling(preview)), 0.1f);
  const auto full = wide_face();
  const auto drawn = faces.package_arrived(3, full, error);
  EXPECT_NE(drawn, full);
  EXPECT_EQ(drawn->avatar.morphs[kAu12].vertex_delta, redefined->avatar.morphs[kAu12].vertex_delta);
  EXPECT_EQ(faces.units_arrived(restore(3, 2), error), full);
  EXPECT_EQ(error, "");
  // Another avatar is untouched by this one's units.
  const auto other = wide_face();
  EXPECT_EQ(faces.package_arrived(4, other, error), other);
}

TEST(RedefinedFaces, ASetPastTheFaceLeavesTheShippedUnitsAndSaysWhy) {
  RedefinedFaces faces;
  std::string error;
  const auto shipped = wide_face();
  faces.package_arrived(5, shipped, error);
  codec::UnitMorphs bad = pull_down(5, 1);
  bad.units[0].moves.push_back({static_cast<std::uint32_t>(model::generic_face().skin.positions.size()), {1, 0, 0}});
  EXPECT_EQ(faces.units_arrived(bad, error), shipped);
  EXPECT_NE(error.find("the face has"), std::string::npos) << error;
}

TEST(RedefinedFaces, AnAvatarThatLeftIsForgotten) {
  RedefinedFaces faces;
  std::string error;
  faces.package_arrived(9, wide_face(), error);
  faces.forget(9);
  EXPECT_EQ(faces.units_arrived(pull_down(9, 1), error), nullptr) << "its package went with it";
}

}  // namespace
}  // namespace fw::client
