// The face lab's physics level (face_overrides.hpp, preview_surface.hpp,
// PROTOCOL.md 5.16 and 5.18): muscle, skin age and looseness overrides
// parsed and clamped, a muscle moving the face where it inserts as the page
// rebuilds it (the frame's action units plus the preview surface), the
// skin's age giving more to the same pull, and a preview keeping its
// physics face awake and unshed.
#include "preview_surface.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "face_overrides.hpp"
#include "fw/model/generic_face.hpp"
#include "fw/model/landmark_template.hpp"
#include "room_simulation.hpp"

namespace fw::server {
namespace {

using codec::OverridePart;

constexpr std::uint8_t kZygomaticMajorLeft = 22, kZygomaticMinorLeft = 20;
constexpr int kLeftMouthCorner = 54;  // 68-point scheme: the person's left mouth corner (x > 0)

RoomSimulationOptions preview_options() {
  RoomSimulationOptions options;
  options.preview = true;
  return options;
}

/// The generic skin as a preview's page rebuilds it: the frame's action
/// units over the neutral face, plus the preview surface's residual.
std::vector<glm::vec3> shown_skin(const RoomSimulation& sim, AvatarId id, bool with_surface = true) {
  const model::GenericFace& face = model::generic_face();
  std::vector<glm::vec3> skin = face.skin.positions;
  const codec::FaceParams& params = sim.face(id);
  for (std::size_t c = 0; c < codec::kAuChannelCount; ++c)
    for (std::size_t v = 0; v < skin.size(); ++v) skin[v] += params.au[c] * face.action_units[c].vertex_delta[v];
  if (!with_surface) return skin;
  const auto surface = sim.preview_surface(id);
  EXPECT_TRUE(surface.has_value());
  if (surface)
    for (const auto& move : surface->moves)
      skin[move.vertex] += glm::vec3(move.delta[0], move.delta[1], move.delta[2]) / codec::kUnitMorphStepsPerUnit;
  return skin;
}

glm::vec3 moved_mm(const std::vector<glm::vec3>& skin, std::size_t vertex) {
  return (skin[vertex] - model::generic_face().skin.positions[vertex]) * model::kMillimetresPerUnit;
}

std::size_t landmark(int index) { return model::generic_face().landmark_vertices[static_cast<std::size_t>(index)]; }

void run(RoomSimulation& sim, int ticks) {
  for (int i = 0; i < ticks; ++i) sim.tick();
}

TEST(PreviewPhysics, MuscleAndSkinOverridesAreClampedAndWhatIsNotThereRefused) {
  FaceOverrides o;
  EXPECT_EQ(set_override(o, {OverridePart::muscle, 41, 0, 30000}), "");
  EXPECT_FLOAT_EQ(o.muscles[41], 1.0f) << "an activation past 1";
  EXPECT_EQ(set_override(o, {OverridePart::muscle, 0, 0, -400}), "");
  EXPECT_FLOAT_EQ(o.muscles[0], 0.0f);
  EXPECT_EQ(set_override(o, {OverridePart::muscle, 22, 0, 2500}), "");
  EXPECT_FLOAT_EQ(o.muscles[22], 0.25f);
  EXPECT_TRUE(o.any_muscle());
  const std::string past = set_override(o, {OverridePart::muscle, 42, 0, 5000});
  EXPECT_NE(past.find("muscle 42 does not exist; use 0 .. 41"), std::string::npos) << past;
  EXPECT_LE(past.size(), codec::kMaxReasonBytes);
  const std::string sided = set_override(o, {OverridePart::muscle, 3, 1, 5000});
  EXPECT_NE(sided.find("side 0"), std::string::npos) << sided;
  EXPECT_FLOAT_EQ(o.muscles[3], 0.0f) << "a refused override leaves the muscle as it was";
  EXPECT_EQ(set_override(o, {OverridePart::skin_age, 0, 0, 12000}), "");
  EXPECT_FLOAT_EQ(o.skin_age, 1.0f);
  EXPECT_EQ(set_override(o, {OverridePart::skin_looseness, 0, 0, 3000}), "");
  EXPECT_FLOAT_EQ(o.skin_looseness, 0.3f);
  EXPECT_EQ(set_override(o, {OverridePart::reset, 0, 0, 0}), "");
  EXPECT_FALSE(o.any_muscle()) << "reset clears the muscles";
  EXPECT_EQ(o.skin_age, 0.0f);
  EXPECT_EQ(o.skin_looseness, 0.0f);
}

TEST(PreviewPhysics, TheLeftZygomaticMajorDrawsTheLeftMouthCornerUpAndOut) {
  RoomSimulation sim(preview_options());
  const AvatarId id = sim.add_avatar({"Ada"});
  run(sim, 15);
  ASSERT_EQ(sim.command(id, OverrideCommand{{OverridePart::muscle, kZygomaticMajorLeft, 0, 10000}}), "");
  run(sim, 45);
  const glm::vec3 corner = moved_mm(shown_skin(sim, id), landmark(kLeftMouthCorner));
  const glm::vec3 other = moved_mm(shown_skin(sim, id), landmark(48));  // the right corner
  std::printf("left corner moved (%.2f, %.2f, %.2f) mm, right corner %.2f mm\n", corner.x, corner.y, corner.z,
              glm::length(other));
  EXPECT_GT(corner.y, 1.0f) << "up";
  EXPECT_GT(corner.x, 0.5f) << "out, toward the person's left";
  EXPECT_LT(glm::length(other), 0.3f * glm::length(corner)) << "one side's muscle";
}

TEST(PreviewPhysics, AMusclesPullBeyondTheActionUnitsArrivesInThePreviewSurface) {
  RoomSimulation sim(preview_options());
  const AvatarId id = sim.add_avatar({"Ada"});
  run(sim, 15);
  ASSERT_TRUE(sim.preview_surface(id));
  EXPECT_TRUE(sim.preview_surface(id)->moves.empty()) << "a neutral face is what its action units rebuild";
  // The zygomatic minor alone is no action unit (it is half of AU 10's
  // muscles): the units explain only part of its pull.
  ASSERT_EQ(sim.command(id, OverrideCommand{{OverridePart::muscle, kZygomaticMinorLeft, 0, 10000}}), "");
  run(sim, 45);
  const auto surface = sim.preview_surface(id);
  ASSERT_TRUE(surface && !surface->moves.empty());
  float largest_mm = 0;
  std::uint32_t at = 0;
  for (const auto& move : surface->moves) {
    const float mm = glm::length(glm::vec3(move.delta[0], move.delta[1], move.delta[2])) /
                     codec::kUnitMorphStepsPerUnit * model::kMillimetresPerUnit;
    if (mm > largest_mm) largest_mm = mm, at = move.vertex;
  }
  const glm::vec3 where = model::generic_face().skin.positions[at];
  std::printf("residual: %zu vertices, largest %.2f mm at vertex %u (%.2f, %.2f)\n", surface->moves.size(),
              largest_mm, at, where.x, where.y);
  EXPECT_GT(largest_mm, 0.2f);
  EXPECT_GT(where.x, 0.0f) << "on the muscle's side";
  // What the page draws follows the simulation: the upper lip on the left
  // rises further with the residual than with the action units alone.
  const std::size_t lip = landmark(52);
  const float with = moved_mm(shown_skin(sim, id), lip).y, without = moved_mm(shown_skin(sim, id, false), lip).y;
  std::printf("upper lip (left) rises %.2f mm drawn with the surface, %.2f mm without\n", with, without);
  EXPECT_GT(with, 0.3f);
}

TEST(PreviewPhysics, OldSkinGivesMoreToTheSamePull) {
  float corner_mm[2] = {};
  for (int aged = 0; aged < 2; ++aged) {
    RoomSimulation sim(preview_options());
    const AvatarId id = sim.add_avatar({"Ada"});
    ASSERT_EQ(sim.command(id, OverrideCommand{{OverridePart::skin_age, 0, 0, static_cast<std::int16_t>(aged * 10000)}}),
              "");
    ASSERT_EQ(sim.command(id, OverrideCommand{{OverridePart::muscle, kZygomaticMajorLeft, 0, 6000}}), "");
    run(sim, 60);
    corner_mm[aged] = glm::length(moved_mm(shown_skin(sim, id), landmark(kLeftMouthCorner)));
  }
  std::printf("left mouth corner under the same pull: %.2f mm young, %.2f mm old\n", corner_mm[0], corner_mm[1]);
  EXPECT_GT(corner_mm[1], corner_mm[0] * 1.05f) << "softer, older skin follows the muscle further";
}

TEST(PreviewPhysics, APreviewKeepsItsPhysicsUnderLoadAndNeverRestsWithAMuscleSet) {
  RoomSimulation sim(preview_options());
  const AvatarId id = sim.add_avatar({"Ada"});
  sim.set_physics_share(0.0);  // the governor sheds every room face it may
  run(sim, 5);
  EXPECT_EQ(sim.physics_faces(), 1u) << "a preview's page shows the physics face itself";
  EXPECT_EQ(sim.kinematic_faces(), 0u);
  ASSERT_EQ(sim.command(id, OverrideCommand{{OverridePart::muscle, 0, 0, 10000}}), "");
  run(sim, 150);  // 5 s: long enough for a face to settle and sleep
  EXPECT_FALSE(sim.resting(id)) << "a driven muscle keeps the preview's face awake";
  ASSERT_EQ(sim.command(id, OverrideCommand{{OverridePart::reset, 0, 0, 0}}), "");
  bool rested = false;
  for (int i = 0; i < 300 && !rested; ++i) {
    sim.tick();
    rested = sim.resting(id);
  }
  EXPECT_TRUE(rested) << "with nothing set the face sleeps again";

  RoomSimulation room(RoomSimulationOptions{});
  room.add_avatar({"Bo"});
  room.set_physics_share(0.0);
  run(room, 2);
  EXPECT_EQ(room.kinematic_faces(), 1u) << "a room's face is still shed";
}

}  // namespace
}  // namespace fw::server
