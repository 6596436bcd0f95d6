// A room's avatar on its own face (RoomSimulation::wear_face): simulated on
// its fit, measured against its own morphs, and taken over from the generic
// face it began with without a jump in what it shows.
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "face_model.hpp"
#include "fw/physics/avatar_tissue.hpp"
#include "room_simulation.hpp"

namespace fw::server {
namespace {

std::shared_ptr<const FaceModel> wide_face() {
  static const auto face = [] {
    auto f = std::make_shared<FaceModel>();
    std::vector<glm::vec2> xy;
    for (const glm::vec3& p : model::generic_face().skin.positions) xy.emplace_back(1.1f * p.x + 0.02f * p.y, 0.93f * p.y);
    f->avatar = model::make_avatar_model(model::generic_face(), xy);
    f->tissue = physics::build_avatar_tissue_model(f->avatar, physics::generic_tissue_model());
    return std::shared_ptr<const FaceModel>(f);
  }();
  return face;
}

float largest_step(const codec::FaceParams& a, const codec::FaceParams& b) {
  float step = 0.0f;
  for (std::size_t c = 0; c < a.au.size(); ++c) step = std::max(step, std::abs(a.au[c] - b.au[c]));
  return step;
}

TEST(RoomOwnFace, AnAvatarJoinedWithItsFaceSimulatesIt) {
  RoomSimulation room(RoomSimulationOptions{});
  AvatarSetup setup{"Ann"};
  setup.asset = "0123456789abcdef0123456789abcdef";
  setup.face = wide_face();
  const AvatarId id = room.add_avatar(setup);
  ASSERT_NE(id, 0u);
  EXPECT_TRUE(room.wears_own_face(id));
  const AvatarId other = room.add_avatar(AvatarSetup{"Bob"});
  EXPECT_FALSE(room.wears_own_face(other));
  for (int t = 0; t < 60; ++t) room.tick();
  for (const float w : room.face(id).au) EXPECT_TRUE(std::isfinite(w) && w >= 0.0f && w <= 1.0f);
}

// A preview holding a smile takes its own face mid-smile: the action units
// it shows go over to the new measurement in kOwnFaceBlendS, tick by tick.
TEST(RoomOwnFace, WearingItsOwnFaceMidSmileDoesNotJump) {
  RoomSimulationOptions options;
  options.preview = true;
  RoomSimulation room(options);
  const AvatarId id = room.add_avatar(AvatarSetup{"Ann"});
  ASSERT_EQ(room.command(id, OverrideCommand{{codec::OverridePart::action_unit, 12, 0, 10000}}), "");
  ASSERT_EQ(room.command(id, OverrideCommand{{codec::OverridePart::action_unit, 27, 0, 6000}}), "");
  for (int t = 0; t < 60; ++t) room.tick();
  codec::FaceParams before = room.face(id);
  room.tick();
  const float settled_step = largest_step(before, room.face(id));
  before = room.face(id);
  const float smile = before.au[codec::au_channel(12, codec::AuSide::left)];
  room.wear_face(id, wide_face());
  EXPECT_TRUE(room.wears_own_face(id));
  float worst = 0.0f;
  for (int t = 0; t < 45; ++t) {
    room.tick();
    worst = std::max(worst, largest_step(before, room.face(id)));
    before = room.face(id);
  }
  const float own_smile = room.face(id).au[codec::au_channel(12, codec::AuSide::left)];
  std::printf("largest step of an action unit in a tick: %.3f settled, %.3f over the switch; AU 12 %.2f -> %.2f\n",
              settled_step, worst, smile, own_smile);
  // The face holds its expression, so what moves a unit here is the switch
  // alone (0.06 measured); measured against the new morphs at once, it
  // would move by 0.2.
  EXPECT_LT(worst, 0.08f) << "the switch would jump";
  EXPECT_GT(own_smile, 0.3f) << "still smiling on its own face";
}

}  // namespace
}  // namespace fw::server
