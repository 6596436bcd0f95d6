#include "face_overrides.hpp"

#include <algorithm>

#include <gtest/gtest.h>

#include "room_simulation.hpp"
#include "script_check.hpp"

namespace fw::server {
namespace {

using codec::AuSide;
using codec::OverridePart;

float channel(const FaceOverrides& o, int au, AuSide side) {
  const auto& value = o.au[static_cast<std::size_t>(codec::au_channel(au, side))];
  return value ? *value : -1.0f;
}

TEST(FaceOverrides, ValuesAreClampedToTheFacesRanges) {
  FaceOverrides o;
  EXPECT_EQ(set_override(o, {OverridePart::emotion, 0, 0, 30000}), "");
  EXPECT_FLOAT_EQ(o.emotions[0], 1.0f) << "an intensity past 1";
  EXPECT_EQ(set_override(o, {OverridePart::emotion, 1, 0, -500}), "");
  EXPECT_FLOAT_EQ(o.emotions[1], 0.0f) << "a negative intensity";
  EXPECT_EQ(set_override(o, {OverridePart::head_yaw, 0, 0, 32000}), "");
  EXPECT_FLOAT_EQ(*o.head_yaw, kMaxHeadYawRad);
  EXPECT_EQ(set_override(o, {OverridePart::eye_pitch, 0, 0, -32000}), "");
  EXPECT_FLOAT_EQ(*o.eye_pitch, -kMaxEyePitchRad);
  EXPECT_EQ(set_override(o, {OverridePart::head_roll, 0, 0, 2500}), "");
  EXPECT_FLOAT_EQ(*o.head_roll, 0.25f) << "a value in range is kept";
  EXPECT_EQ(set_override(o, {OverridePart::blush, 1, 0, 12000}), "");
  EXPECT_FLOAT_EQ(*o.blush[1], 1.0f);
}

TEST(FaceOverrides, SidesOfActionUnitsAndLids) {
  FaceOverrides o;
  EXPECT_EQ(set_override(o, {OverridePart::action_unit, 12, 1, 8000}), "");
  EXPECT_FLOAT_EQ(channel(o, 12, AuSide::left), 0.8f);
  EXPECT_FLOAT_EQ(channel(o, 12, AuSide::right), -1.0f) << "the right side was not asked for";
  EXPECT_EQ(set_override(o, {OverridePart::action_unit, 12, 0, 3000}), "");
  EXPECT_FLOAT_EQ(channel(o, 12, AuSide::right), 0.3f) << "both sides";
  EXPECT_EQ(set_override(o, {OverridePart::action_unit, 26, 0, 5000}), "");
  EXPECT_FLOAT_EQ(channel(o, 26, AuSide::both), 0.5f);
  EXPECT_EQ(set_override(o, {OverridePart::lids, 0, 2, 10000}), "");
  EXPECT_FALSE(o.lid_left);
  EXPECT_FLOAT_EQ(*o.lid_right, 1.0f);
}

TEST(FaceOverrides, WhatTheFaceDoesNotHaveIsRefusedAndLeavesTheRest) {
  FaceOverrides o;
  ASSERT_EQ(set_override(o, {OverridePart::emotion, 0, 0, 5000}), "");
  const std::string au3 = set_override(o, {OverridePart::action_unit, 3, 0, 5000});
  EXPECT_NE(au3.find("action unit 3 is not one the face shows"), std::string::npos) << au3;
  EXPECT_NE(au3.find("12"), std::string::npos) << "the message lists the units there are: " << au3;
  const std::string midline = set_override(o, {OverridePart::action_unit, 26, 1, 5000});
  EXPECT_NE(midline.find("both sides"), std::string::npos) << midline;
  EXPECT_NE(set_override(o, {OverridePart::emotion, 6, 0, 5000}), "");
  EXPECT_NE(set_override(o, {OverridePart::blush, 5, 0, 5000}), "");
  EXPECT_FLOAT_EQ(o.emotions[0], 0.5f) << "a refused override changed another";
  for (const auto& channel : o.au) EXPECT_FALSE(channel) << "a refused action unit was set";
}

TEST(FaceOverrides, BehaviourOffStartsNeutralAndOverridesWin) {
  codec::FaceParams face;
  face.set_au(4, 0.9f);  // what the behaviour made: a frown, turned away, blushing
  face.head_yaw_rad = 0.5f;
  face.blush[0] = 0.7f;
  FaceOverrides o;
  apply_overrides(o, face, nullptr);
  EXPECT_EQ(face.au_intensity(4), 0.0f) << "behaviour off: neutral";
  EXPECT_EQ(face.head_yaw_rad, 0.0f);
  EXPECT_EQ(face.blush[0], 0.0f);

  ASSERT_EQ(set_override(o, {OverridePart::emotion, 0, 0, 10000}), "");  // joy
  ASSERT_EQ(set_override(o, {OverridePart::blush, 1, 0, 6000}), "");
  ASSERT_EQ(set_override(o, {OverridePart::head_pitch, 0, 0, -2000}), "");
  face = {};
  apply_overrides(o, face, nullptr);
  EXPECT_GT(face.au_intensity(12), 0.3f) << "joy pulls the lip corners";
  EXPECT_FLOAT_EQ(face.blush[1], 0.6f);
  EXPECT_FLOAT_EQ(face.head_pitch_rad, -0.2f);

  ASSERT_EQ(set_override(o, {OverridePart::action_unit, 12, 0, 0}), "");
  face = {};
  apply_overrides(o, face, nullptr);
  EXPECT_EQ(face.au_intensity(12), 0.0f) << "an action unit set wins over the emotion";

  ASSERT_EQ(set_override(o, {OverridePart::behaviour, 0, 0, 1}), "");
  face = {};
  face.set_au(4, 0.9f);
  apply_overrides(o, face, nullptr);
  EXPECT_FLOAT_EQ(face.au_intensity(4), 0.9f) << "behaviour on: its frown stays under the overrides";

  ASSERT_EQ(set_override(o, {OverridePart::reset, 0, 0, 0}), "");
  EXPECT_FALSE(o.behaviour);
  EXPECT_EQ(o.emotions[0], 0.0f);
}

TEST(FaceOverrides, APreviewSimulationHoldsItsFaceAndARoomRefuses) {
  RoomSimulationOptions options;
  options.preview = true;
  RoomSimulation preview(options);
  const AvatarId id = preview.add_avatar({"Ada"});
  for (int i = 0; i < 30; ++i) preview.tick();
  EXPECT_LT(preview.face(id).au_intensity(12), 0.05f) << "a preview's face starts neutral";
  EXPECT_EQ(preview.command(id, OverrideCommand{{OverridePart::emotion, 0, 0, 10000}}), "");
  for (int i = 0; i < 30; ++i) preview.tick();
  EXPECT_GT(preview.face(id).au_intensity(12), 0.3f) << "joy through the physics face";

  RoomSimulation room(RoomSimulationOptions{});
  const AvatarId other = room.add_avatar({"Bo"});
  EXPECT_NE(room.command(other, OverrideCommand{{OverridePart::emotion, 0, 0, 10000}}), "");
}

TEST(FaceOverrides, AFacsSentencePlaysOnAPreviewWithBehaviourOff) {
  RoomSimulationOptions options;
  options.preview = true;
  RoomSimulation preview(options);
  const AvatarId id = preview.add_avatar({"Ada"});
  ASSERT_EQ(preview.command(id, FacsCommand{"ClearAllFrame\nBeginKeyFrame\nBeginKeyFrame\n 12 1.0\nAnimate 5 \"Texture\"\nend\n"}),
            "");
  float most = 0;
  for (int i = 0; i < 45; ++i) {
    preview.tick();
    most = std::max(most, preview.face(id).au_intensity(12));
  }
  EXPECT_GT(most, 0.3f) << "the sentence did not show with behaviour off";
}

// A vascular emotion is colour only: with behaviour off the preview's face
// starts neutral every tick, which cleared the episode's blush.
TEST(FaceOverrides, AVascularScriptColoursAPreviewWithBehaviourOff) {
  RoomSimulationOptions options;
  options.preview = true;
  RoomSimulation preview(options);
  const AvatarId id = preview.add_avatar({"Ada"});
  ASSERT_EQ(preview.command(id, FacsCommand{"[emotion glow [stage1 duration 100 [expression warm intensity 1]]]\n"
                                            "[expression warm [mpca cheeks intensity 1]]\n"}),
            "");
  float most = 0;
  for (int i = 0; i < 8 * 30; ++i) {  // 8 s
    preview.tick();
    const codec::FaceParams face = preview.face(id);
    most = std::max(most, *std::max_element(face.blush.begin(), face.blush.end()));
  }
  EXPECT_GT(most, 0.2f) << "the script's blush did not show with behaviour off";
}

TEST(ScriptCheck, TheFirstErrorWithItsLineAndColumn) {
  EXPECT_EQ(check_script("ClearAllFrame\nBeginKeyFrame\nBeginKeyFrame\n 12 1.0\nAnimate 5 \"Texture\"\nend\n"), "");
  const std::string error = check_script("ClearAllFrame\nBeginKeyFrame\n 12 oops\nend\n");
  EXPECT_EQ(error.rfind("line 3, column ", 0), 0u) << error;
  EXPECT_EQ(check_script("").rfind("line 1, column 1: ", 0), 0u) << "an empty script is no expression";
  // Well formed but past a room's bounds: what playing it would answer.
  const std::string too_long = check_script("ClearAllFrame BeginKeyFrame 12 1.0 Animate 700 \"Texture\" end");
  EXPECT_NE(too_long.find("at most 60 s"), std::string::npos) << too_long;
}

}  // namespace
}  // namespace fw::server
