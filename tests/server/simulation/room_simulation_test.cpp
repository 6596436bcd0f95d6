// server/simulation/room_simulation.cpp with the physics face on: its level of
// detail under load. (Commands and events without physics are tested in
// tests/behavior/simulate_command_test.cpp.)
#include "room_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "neutral_speaker.hpp"

namespace fw::server {
namespace {

RoomSimulation room_with_physics(std::uint64_t seed = 11) {
  RoomSimulationOptions o;
  o.seed = seed;
  return RoomSimulation(o);
}

// "face 3" (built by appending: GCC 12 warns falsely about "f" + to_string).
std::string face_name(int i) {
  std::string name = "face ";
  name += std::to_string(i);
  return name;
}

// AU 12 (lip-corner puller), both sides.
float smile(const codec::FaceParams& face) { return face.au_intensity(12); }

TEST(RoomSimulationLevelOfDetail, EveryFaceRunsPhysicsByDefault) {
  RoomSimulation room = room_with_physics();
  for (int i = 0; i < 4; ++i) room.add_avatar({face_name(i), false});
  room.tick();
  EXPECT_EQ(room.physics_faces(), 4u);
  EXPECT_EQ(room.kinematic_faces(), 0u);
}

TEST(RoomSimulationLevelOfDetail, WithoutPhysicsFacesStillFollowTheirTargets) {
  RoomSimulation room = room_with_physics();
  const AvatarId a = room.add_avatar({"a", true});
  room.set_physics_share(0);
  ASSERT_EQ(room.command(a, ExpressCommand{"joy", 1, 3}), "");
  for (int i = 0; i < 45; ++i) room.tick();
  EXPECT_EQ(room.physics_faces(), 0u);
  EXPECT_EQ(room.kinematic_faces(), 1u);
  EXPECT_GT(smile(room.face(a)), 0.5f);
  room.remove_avatar(a);
  const AvatarId b = room.add_avatar({"b", true});
  for (int i = 0; i < 3 * 30; ++i) room.tick();
  // A face that has held still for a while rests, though it never had physics.
  bool rested = false;
  for (int i = 0; i < 10 * 30 && !rested; ++i) {
    room.tick();
    rested = room.resting(b);
  }
  EXPECT_TRUE(rested);
}

// By default the room's physics face is solved by projective dynamics
// (--physics-mass-spring: by mass-spring). Its smile follows the mass-spring one closely (the solvers settle
// within 0.12 mm of each other, avatar/physics README) but is not the same
// number: the option reached the solver.
TEST(RoomSimulationSolver, ProjectiveDynamicsSmilesAsMassSpringDoes) {
  auto smile_after = [](bool projective, int ticks) {
    RoomSimulationOptions o;
    o.seed = 11;
    o.physics_projective = projective;
    RoomSimulation room(o);
    const AvatarId a = room.add_avatar({"a", false});
    EXPECT_EQ(room.command(a, ExpressCommand{"joy", 1, 3}), "");
    for (int i = 0; i < ticks; ++i) room.tick();
    return smile(room.face(a));
  };
  const float mass_spring = smile_after(false, 45), projective = smile_after(true, 45);
  EXPECT_GT(projective, 0.5f);
  EXPECT_NEAR(projective, mass_spring, 0.1f);
  EXPECT_NE(projective, mass_spring);
  EXPECT_LT(smile_after(true, 2), 0.5f * projective) << "the tissue takes its time";
}

// A held smile: the physics face comes to rest on it and costs nothing,
// yet the smile on the face still wavers (never frozen on its plateau). It
// rests for all 180 ticks at two projective steps a frame; at one it
// rested for 81 with the bulk curve on (132 linear; 70
// before the projective solver's bond to the bone, and 103 on a uniform
// 12 mm of tissue: with the face's regional depths, the thin lid and
// forehead columns, the projective face took 0.6 s longer to settle on
// joy).
TEST(RoomSimulationPlateau, AHeldExpressionLivesWhileTheTissueRests) {
  RoomSimulation room = room_with_physics();
  const AvatarId a = room.add_avatar({"a", true});
  ASSERT_EQ(room.command(a, ExpressCommand{"joy", 0.8f, 20}), "");
  for (int i = 0; i < 4 * 30; ++i) room.tick();  // onto the plateau
  int resting = 0;
  float lo = 1, hi = 0;
  for (int i = 0; i < 6 * 30; ++i) {
    room.tick();
    resting += room.resting(a) ? 1 : 0;
    lo = std::min(lo, smile(room.face(a)));
    hi = std::max(hi, smile(room.face(a)));
  }
  std::printf("tissue resting %d of 180 ticks; the smile between %.3f and %.3f\n", resting, lo, hi);
  EXPECT_GT(resting, 60) << "the physics face should rest on a held expression";
  EXPECT_GT(hi - lo, 0.02f) << "the smile is frozen";
  EXPECT_GT(lo, 0.4f);
}

// Lips apart plus jaw drop: how open the mouth is.
float mouth_open(const codec::FaceParams& face) { return face.au_intensity(25) + face.au_intensity(26); }

// A chat line is said: the writer's mouth opens and closes several times a
// second while it speaks, and is still before and after.
TEST(RoomSimulationSpeech, AChatLineIsSpokenWithTheMouth) {
  RoomSimulation room = room_with_physics();
  // What moves the mouth below is the line alone.
  const test::NeutralSpeaker spoken =
      test::neutral_speaker_says(room, "hello there, it is a lovely morning for a walk by the river");
  ASSERT_EQ(spoken.refused, "");
  const AvatarId a = spoken.id;
  float before = 0;
  for (const codec::FaceParams& face : spoken.before) before = std::max(before, mouth_open(face));
  std::vector<float> opening;
  for (const codec::FaceParams& face : spoken.during) opening.push_back(mouth_open(face));
  ASSERT_GT(opening.size(), 60u) << "the line was not said for long";
  // Open-close cycles: each opening that rises at least 0.1 above the
  // closing before it and falls 0.1 after (a syllable seen at 30 Hz).
  const float lo = *std::min_element(opening.begin(), opening.end());
  const float hi = *std::max_element(opening.begin(), opening.end());
  int cycles = 0;
  bool rising = true;
  float low = opening.front(), high = opening.front();
  for (const float v : opening) {
    if (rising) {
      low = std::min(low, v);
      if (v >= low + 0.1f) rising = false, high = v;
    } else {
      high = std::max(high, v);
      if (v <= high - 0.1f) rising = true, low = v, ++cycles;
    }
  }
  const double per_second = cycles / (static_cast<double>(opening.size()) / 30.0);
  std::printf("mouth before %.2f; while speaking %.2f .. %.2f, %.1f openings a second over %.1f s\n", before, lo, hi,
              per_second, opening.size() / 30.0);
  EXPECT_LT(before, 0.05f) << "the mouth moved before the line";
  EXPECT_GT(hi - lo, 0.3f) << "the mouth hardly moves";
  EXPECT_GE(per_second, 3.5);  // syllables: about 4-5 a second (Greenberg 1999)
  EXPECT_LE(per_second, 6.0);
  for (int i = 0; i < 15; ++i) room.tick();
  EXPECT_LT(mouth_open(room.face(a)), 0.05f) << "the mouth is still after the line";
}

// Lines written while the avatar speaks wait their turn, a few at most.
TEST(RoomSimulationSpeech, LinesWaitTheirTurnAndTooManyAreNotSaid) {
  RoomSimulation room = room_with_physics();
  const AvatarId a = room.add_avatar({"a", true});
  room.tick();
  room.chat(a, "the first line, said at once");
  for (int i = 0; i < 4; ++i) room.chat(a, "and one more");
  bool refused = false;
  for (const RoomEvent& e : room.take_events()) refused |= e.what.find("speech: a line not said") != std::string::npos;
  EXPECT_TRUE(refused) << "five lines at once: the fifth waits behind three";
  // The four said lines follow one another.
  int starts = 0;
  bool was = false;
  for (int i = 0; i < 30 * 20; ++i) {
    room.tick();
    const bool now = room.speaking(a);
    starts += now && !was ? 1 : 0;
    was = now;
  }
  EXPECT_EQ(starts, 4);
}

TEST(RoomSimulationLevelOfDetail, ASharePicksTheSameFacesEveryTick) {
  RoomSimulation room = room_with_physics();
  for (int i = 0; i < 16; ++i) room.add_avatar({face_name(i), false});
  room.set_physics_share(0.5);
  std::set<std::size_t> counts;
  for (int i = 0; i < 30; ++i) {
    room.tick();
    counts.insert(room.physics_faces());
    ASSERT_EQ(room.physics_faces() + room.kinematic_faces(), 16u);
  }
  ASSERT_EQ(counts.size(), 1u) << "the same faces keep physics";
  EXPECT_GT(*counts.begin(), 2u);
  EXPECT_LT(*counts.begin(), 14u);
}

TEST(RoomSimulationLevelOfDetail, GettingPhysicsBackBlendsWithoutAJumpOrADip) {
  // The same expression with and without the switch. While the expression
  // is held, the face that gets physics back neither jumps nor sags toward
  // the neutral face its tissue was left in, and it ends where physics puts
  // the face that never lost it.
  constexpr int kSwitchTick = 20;
  auto run = [](bool switching, std::vector<float>& track) {
    RoomSimulation room = room_with_physics();
    const AvatarId a = room.add_avatar({"a", true});
    EXPECT_EQ(room.command(a, ExpressCommand{"surprise", 1, 4}), "");
    if (switching) room.set_physics_share(0);
    for (int i = 0; i < 90; ++i) {
      if (switching && i == kSwitchTick) room.set_physics_share(1);
      room.tick();
      track.push_back(room.face(a).au_intensity(26));
    }
    return room.face(a);
  };
  std::vector<float> steady_track, switching_track;
  const codec::FaceParams steady = run(false, steady_track);
  const codec::FaceParams switched = run(true, switching_track);
  float steady_step = 0;
  for (std::size_t i = 1; i < steady_track.size(); ++i)
    steady_step = std::max(steady_step, std::abs(steady_track[i] - steady_track[i - 1]));
  const float at_switch = switching_track[kSwitchTick - 1];
  const float floor = std::min(at_switch, steady_track.back()) - 0.05f;
  for (std::size_t i = kSwitchTick; i < 90; ++i) {
    EXPECT_LE(std::abs(switching_track[i] - switching_track[i - 1]), steady_step * 1.5f + 0.01f) << "tick " << i;
    EXPECT_GE(switching_track[i], floor) << "tick " << i << ": the face sags toward its stale tissue";
  }
  for (std::size_t c = 0; c < steady.au.size(); ++c) EXPECT_NEAR(switched.au[c], steady.au[c], 0.05f) << "channel " << c;
}

}  // namespace
}  // namespace fw::server
