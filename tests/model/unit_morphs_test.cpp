// Redefined units (unit_morphs.hpp): carried onto a fit as the shipped units
// are, through the wire's form unchanged, and restored by an empty set.
#include "fw/model/unit_morphs.hpp"

#include <set>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "fw/model/face_reconstruction.hpp"
#include "fw/model/motion_cloning.hpp"

namespace fw::model {
namespace {

AvatarModel wide_face() {
  std::vector<glm::vec2> xy;
  for (const glm::vec3& p : generic_face().skin.positions) xy.emplace_back(1.1f * p.x + 0.02f * p.y, 0.93f * p.y);
  return make_avatar_model(generic_face(), xy);
}

std::set<std::uint32_t> vertices_of(FaceRegion region) {
  const GenericFace& face = generic_face();
  std::set<std::uint32_t> out;
  for (std::size_t f = 0; f < face.skin.triangles.size(); ++f)
    if (face.triangle_regions[f] == region)
      for (int k = 0; k < 3; ++k) out.insert(face.skin.triangles[f][k]);
  return out;
}

// The nose pulled up 0.06 units (about 4 mm) and forward a little.
Morph nose_lift() {
  Morph m;
  m.vertex_delta.assign(generic_face().skin.positions.size(), glm::vec3(0.0f));
  m.uv_delta.assign(m.vertex_delta.size(), glm::vec2(0.0f));
  for (const std::uint32_t v : vertices_of(FaceRegion::nose)) m.vertex_delta[v] = glm::vec3(0.0f, 0.06f, 0.01f);
  return m;
}

const std::size_t kAu9 = static_cast<std::size_t>(codec::au_channel(9, codec::AuSide::both));

TEST(UnitMorphs, ARedefinedUnitIsCarriedOntoTheFitAsTheShippedOnesAre) {
  AvatarModel avatar = wide_face();
  const AvatarModel shipped = avatar;
  set_unit_morphs(avatar, generic_face(), {{kAu9, nose_lift()}});
  const Morph expected = clone_morph(nose_lift(), avatar.jacobians);
  for (std::size_t v = 0; v < expected.vertex_delta.size(); ++v)
    EXPECT_EQ(avatar.morphs[kAu9].vertex_delta[v], expected.vertex_delta[v]) << v;
  // On a wider face the lift is not simply copied: the fit's local map applies.
  EXPECT_NE(avatar.morphs[kAu9].vertex_delta, nose_lift().vertex_delta);
  for (std::size_t c = 0; c < avatar.morphs.size(); ++c) {
    if (c != kAu9) {
      EXPECT_EQ(avatar.morphs[c].vertex_delta, shipped.morphs[c].vertex_delta) << c;
    }
  }
}

TEST(UnitMorphs, ReconstructionWithTheRedefinedUnitMovesItsRegionAndOnlyIt) {
  AvatarModel avatar = wide_face();
  set_unit_morphs(avatar, generic_face(), {{kAu9, nose_lift()}});
  codec::FaceParams on;
  on.au[kAu9] = 1.0f;
  const FaceShape neutral = reconstruct_face(avatar, {});
  const FaceShape moved = reconstruct_face(avatar, on);
  const std::set<std::uint32_t> nose = vertices_of(FaceRegion::nose);
  std::size_t lifted = 0;
  for (std::uint32_t v = 0; v < neutral.positions.size(); ++v) {
    const glm::vec3 d = moved.positions[v] - neutral.positions[v];
    if (nose.contains(v)) {
      lifted += d.y > 0.05f;
    } else {
      EXPECT_EQ(d, glm::vec3(0.0f)) << "vertex " << v << " is outside the nose";
    }
  }
  EXPECT_EQ(lifted, nose.size());
  // The shipped AU 9 moves more of the face than the nose.
  const FaceShape shipped = reconstruct_face(wide_face(), on);
  std::size_t shipped_outside = 0;
  for (std::uint32_t v = 0; v < neutral.positions.size(); ++v)
    shipped_outside += !nose.contains(v) && glm::length(shipped.positions[v] - neutral.positions[v]) > 1e-5f;
  EXPECT_GT(shipped_outside, 0u);
}

TEST(UnitMorphs, TheWireCarriesTheMorphAsTheServerKeepsIt) {
  const Morph lift = nose_lift();
  const codec::UnitMorphs::Unit unit = unit_morph_message(kAu9, lift);
  EXPECT_EQ(unit.channel, kAu9);
  EXPECT_EQ(unit.moves.size(), vertices_of(FaceRegion::nose).size());
  const codec::UnitMorphs message{7, 1, {unit}};
  std::vector<std::uint8_t> bytes;
  codec::write_message(message, bytes);
  codec::UnitMorphs read;
  ASSERT_EQ(codec::read_message(bytes, read), codec::MessageError::ok);
  std::string error;
  const auto set = unit_morph_set(read, generic_face().skin.positions.size(), error);
  ASSERT_TRUE(set) << error;
  const Morph carried = as_carried(kAu9, lift);
  EXPECT_EQ(set->at(kAu9).vertex_delta, carried.vertex_delta);
  for (std::size_t v = 0; v < lift.vertex_delta.size(); ++v)
    EXPECT_LE(glm::length(carried.vertex_delta[v] - lift.vertex_delta[v]), 1.0f / codec::kUnitMorphStepsPerUnit);
  // A face with fewer vertices than the morph names refuses it.
  EXPECT_FALSE(unit_morph_set(read, 10, error));
  EXPECT_NE(error.find("moves vertex"), std::string::npos) << error;
}

TEST(UnitMorphs, AnEmptySetRestoresTheShippedUnits) {
  AvatarModel avatar = wide_face();
  const AvatarModel shipped = avatar;
  set_unit_morphs(avatar, generic_face(), {{kAu9, nose_lift()}});
  set_unit_morphs(avatar, generic_face(), {});
  for (std::size_t c = 0; c < avatar.morphs.size(); ++c) {
    EXPECT_EQ(avatar.morphs[c].vertex_delta, shipped.morphs[c].vertex_delta) << c;
    EXPECT_EQ(avatar.morphs[c].uv_delta, shipped.morphs[c].uv_delta) << c;
  }
  // The generic face itself (no fit) takes the morph as it is.
  AvatarModel generic = generic_avatar_model();
  set_unit_morphs(generic, generic_face(), {{kAu9, nose_lift()}});
  EXPECT_EQ(generic.morphs[kAu9].vertex_delta, nose_lift().vertex_delta);
}

}  // namespace
}  // namespace fw::model
