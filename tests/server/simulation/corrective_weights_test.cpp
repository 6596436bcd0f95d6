// server/simulation/room_simulation.cpp: the corrective weights a room's
// faces carry in FaceParams (the physics face's residual on the asset's
// corrective components).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "fw/model/generic_face.hpp"
#include "neutral_speaker.hpp"
#include "room_simulation.hpp"
#include "test_paths.hpp"

namespace fw::server {
namespace {

float largest(const codec::FaceParams& face) {
  float most = 0;
  for (float w : face.corrective) most = std::max(most, std::abs(w));
  return most;
}

RoomSimulation room(std::uint64_t seed) {
  RoomSimulationOptions o;
  o.seed = seed;
  return RoomSimulation(o);
}

// Surprise opens the jaw and lifts the brows: the tissue lags and bulges
// beyond what the action units rebuild, and the weights say so.
TEST(RoomCorrectiveWeights, APhysicsFaceCarriesThemWhileItMoves) {
  ASSERT_FALSE(model::generic_face().correctives.empty()) << "run `make facegen`";
  RoomSimulation r = room(5);
  const AvatarId a = r.add_avatar({"a", true});
  ASSERT_EQ(r.command(a, ExpressCommand{"surprise", 1, 2}), "");
  float most = 0;
  for (int i = 0; i < 60; ++i) {
    r.tick();
    most = std::max(most, largest(r.face(a)));
    for (float w : r.face(a).corrective) ASSERT_LE(std::abs(w), 1.0f);
  }
  EXPECT_EQ(r.physics_faces(), 1u);
  EXPECT_GT(most, 0.1f);
}

TEST(RoomCorrectiveWeights, AKinematicFaceCarriesNone) {
  RoomSimulation r = room(5);
  const AvatarId a = r.add_avatar({"a", true});
  r.set_physics_share(0);
  ASSERT_EQ(r.command(a, ExpressCommand{"surprise", 1, 2}), "");
  for (int i = 0; i < 60; ++i) {
    r.tick();
    ASSERT_EQ(largest(r.face(a)), 0.0f) << "tick " << i;
  }
  EXPECT_EQ(r.kinematic_faces(), 1u);
}

// A face given physics back fades its corrective weights in with the AUs'
// blend: never a jump from 0 to the physics face's weights.
TEST(RoomCorrectiveWeights, AFaceBackToPhysicsBlendsThemIn) {
  RoomSimulation r = room(5);
  const AvatarId a = r.add_avatar({"a", true});
  r.set_physics_share(0);
  ASSERT_EQ(r.command(a, ExpressCommand{"surprise", 1, 4}), "");
  for (int i = 0; i < 20; ++i) r.tick();
  r.set_physics_share(1);
  float last = 0, biggest_step = 0, most = 0;
  for (int i = 0; i < 60; ++i) {
    r.tick();
    const float now = largest(r.face(a));
    biggest_step = std::max(biggest_step, now - last);
    most = std::max(most, now);
    last = now;
  }
  EXPECT_GT(most, 0.05f) << "physics is back";
  EXPECT_LT(biggest_step, 0.6f) << "the weights come in over the blend";
}

// While a line is said the frames show its track's mouth; the tissue is not
// given it, so its corrective weights carry no residual of a mouth of its
// own (given the track, a neutral face's tissue followed late and at half,
// and its weights reached 0.5 on the track's mouth).
TEST(RoomCorrectiveWeights, ASpeakingFaceLaysNoMouthOfItsTissueOnTheTracks) {
  RoomSimulation r = room(5);
  const test::NeutralSpeaker line =
      test::neutral_speaker_says(r, "a baby bought a puppy, mom, maybe the map is in the pub");
  ASSERT_EQ(line.refused, "");
  float before = 0, during = 0, jaw_lo = 1, jaw_hi = 0;
  for (const codec::FaceParams& face : line.before) before = std::max(before, largest(face));
  for (const codec::FaceParams& face : line.during) {
    during = std::max(during, largest(face));
    jaw_lo = std::min(jaw_lo, face.au_intensity(26));
    jaw_hi = std::max(jaw_hi, face.au_intensity(26));
  }
  const int spoken = static_cast<int>(line.during.size());
  std::printf("corrective weights: at most %.3f before the line, %.3f while it is said (%d ticks, jaw %.2f .. %.2f)\n",
              before, during, spoken, jaw_lo, jaw_hi);
  ASSERT_GT(spoken, 45);
  EXPECT_GT(jaw_hi - jaw_lo, 0.2f) << "the track's jaw is shown";
  EXPECT_LT(during, before + 0.05f);
}

TEST(RoomCorrectiveWeights, AFaceWithRedefinedUnitsCarriesNone) {
  RoomSimulation r = room(5);
  const AvatarId a = r.add_avatar({"a", true});
  std::ifstream in(test::source_path("avatar/behavior/script/examples/au1.fws"));
  std::stringstream script;
  script << in.rdbuf();
  ASSERT_EQ(r.command(a, FacsCommand{script.str()}), "");
  ASSERT_TRUE(r.unit_morphs(a));
  ASSERT_EQ(r.command(a, ExpressCommand{"surprise", 1, 2}), "");
  for (int i = 0; i < 60; ++i) {
    r.tick();
    ASSERT_EQ(largest(r.face(a)), 0.0f) << "tick " << i;
  }
}

}  // namespace
}  // namespace fw::server
