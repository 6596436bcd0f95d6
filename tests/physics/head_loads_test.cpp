// A head that tilts or turns loads its tissue: the kernel's field, the
// calibration against people lying down, the direction of the sag when
// the head bows, the lag of a turn, and a resting face that sleeps through
// the head's sway.
#include <cmath>
#include <numbers>
#include <set>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "fw/model/generic_face.hpp"
#include "fw/model/landmark_template.hpp"
#include "fw/physics/face_simulation.hpp"
#include "fw/physics/head_loads.hpp"
#include "generic_tissue.hpp"

namespace fw::physics {
namespace {

constexpr double kFrame = 1.0 / 30.0;
constexpr float kMm = model::kMillimetresPerUnit;
constexpr float kScale = 0.5f;

HeadLoad advance_to(HeadMotion& motion, const HeadPose& pose) {
  motion.set_pose(pose);
  return motion.advance(kFrame, kScale);
}

TEST(HeadLoads, AnUprightStillHeadLoadsNothing) {
  HeadMotion motion;
  for (int f = 0; f < 3; ++f) EXPECT_TRUE(advance_to(motion, {}).none());
}

TEST(HeadLoads, ABowedHeadFeelsGravityTowardTheFaceFront) {
  HeadMotion motion;
  const float bow = 0.5f;
  HeadLoad load;
  for (int f = 0; f < 3; ++f) load = advance_to(motion, {0.0f, -bow, 0.0f, {}});
  // What the upright rest shape does not balance: 2 g sin(bow / 2) in size.
  EXPECT_NEAR(glm::length(load.uniform), kScale * 2.0f * kGravityUnits * std::sin(bow / 2), 1e-3f);
  EXPECT_GT(load.uniform.z, 0.0f) << "toward the front of the face";
  EXPECT_GT(load.uniform.y, 0.0f) << "less of gravity's pull down the face";
  EXPECT_EQ(load.linear, glm::mat3(0.0f)) << "a held head has no turn";
}

TEST(HeadLoads, ASteadyTurnPullsOutwardAndASpeedingOneBackward) {
  // yaw = a t^2 / 2: omega = a t about y, alpha = a.
  const float a = 3.0f;
  HeadMotion motion;
  HeadLoad load;
  const int frames = 10;
  for (int f = 0; f <= frames; ++f) {
    const float t = static_cast<float>(f * kFrame);
    load = advance_to(motion, {0.5f * a * t * t, 0.0f, 0.0f, {}});
  }
  // The backward difference lags half a frame: omega at t - dt / 2.
  const float omega = a * static_cast<float>((frames - 0.5) * kFrame);
  // -(skew(alpha) + skew(omega)^2) times the scale, column-major.
  EXPECT_NEAR(load.linear[0][0], kScale * omega * omega, 0.02f * kScale * omega * omega) << "centripetal, x";
  EXPECT_NEAR(load.linear[2][2], kScale * omega * omega, 0.02f * kScale * omega * omega) << "centripetal, z";
  EXPECT_NEAR(load.linear[1][1], 0.0f, 1e-4f) << "nothing along the axis";
  EXPECT_NEAR(load.linear[2][0], -kScale * a, 0.02f * kScale * a) << "the speed-up, z into x";
  EXPECT_NEAR(load.linear[0][2], kScale * a, 0.02f * kScale * a) << "the speed-up, x into z";
  // A point in front of the pivot (the nose) is pushed against the turn.
  const glm::vec3 nose = model::kNeckPivot + glm::vec3(0.0f, 0.0f, 2.0f);
  EXPECT_LT(load.at(nose).x, 0.0f);
}

TEST(HeadLoads, AJumpIsACutNotATurn) {
  HeadMotion motion;
  advance_to(motion, {});
  const HeadLoad load = advance_to(motion, {1.0f, 0.0f, 0.0f, {}});  // 30 rad/s: put there
  EXPECT_EQ(load.linear, glm::mat3(0.0f));
  EXPECT_NEAR(glm::length(load.uniform), 0.0f, 1e-5f) << "a pure yaw leaves gravity where it was";
  const HeadLoad next = advance_to(motion, {1.0f, 0.0f, 0.0f, {}});
  EXPECT_TRUE(next.none()) << "and the head then holds still";
}

std::set<std::size_t> vertices_of(std::initializer_list<model::FaceRegion> regions) {
  const auto& face = model::generic_face();
  std::set<std::size_t> out;
  for (std::size_t t = 0; t < face.skin.triangles.size(); ++t)
    for (const model::FaceRegion r : regions)
      if (face.triangle_regions[t] == r)
        for (int k = 0; k < 3; ++k) out.insert(face.skin.triangles[t][k]);
  return out;
}

// Mean displacement of `vertices` from rest, mm.
glm::vec3 mean_shift_mm(const FaceSimulation& sim, const std::set<std::size_t>& vertices) {
  const auto surface = sim.surface();
  glm::vec3 sum(0.0f);
  for (const std::size_t v : vertices) sum += surface[v] - model::generic_face().skin.positions[v];
  return sum / static_cast<float>(vertices.size()) * kMm;
}

FaceSimulation settled_at(Solver solver, const HeadPose& pose) {
  SimulationOptions options;
  options.solver = solver;
  FaceSimulation sim(test::generic_tissue(), options);
  sim.set_head_pose(pose);
  for (int f = 0; f < 150 && !(f > 0 && sim.at_rest()); ++f) sim.step(kFrame);
  return sim;
}

const std::set<std::size_t>& lower_face() {
  using model::FaceRegion;
  static const auto v = vertices_of({FaceRegion::chin, FaceRegion::jaw_right, FaceRegion::jaw_left, FaceRegion::lower_lip,
                                     FaceRegion::mouth_corner_right, FaceRegion::mouth_corner_left});
  return v;
}

// Hernandez et al. 2022 (175 adults, 3D surface scans upright and supine):
// lying down moves the lower face 1.17 mm toward the forehead. The load
// scale is calibrated on it (TissueMaterial::load_scale); this holds it.
TEST(HeadLoadsOnTheFace, LyingDownMovesTheLowerFaceAsFarAsInPeople) {
  for (const Solver solver : {Solver::projective, Solver::mass_spring}) {
    const FaceSimulation sim = settled_at(solver, {0.0f, std::numbers::pi_v<float> / 2, 0.0f, {}});
    const glm::vec3 shift = mean_shift_mm(sim, lower_face());
    EXPECT_GT(shift.y, 0.9f) << "solver " << int(solver);
    EXPECT_LT(shift.y, 1.45f) << "solver " << int(solver);
    EXPECT_LT(shift.z, 0.0f) << "and back toward the bone, solver " << int(solver);
  }
}

// Park et al. 2020 (3D imaging in postures): bowing the head pulls the
// lower face forward and down, more than the brow.
TEST(HeadLoadsOnTheFace, ABowedHeadPullsTheLowerFaceForward) {
  const FaceSimulation sim = settled_at(Solver::projective, {0.0f, -0.5f, 0.0f, {}});
  const glm::vec3 lower = mean_shift_mm(sim, lower_face());
  const glm::vec3 forehead = mean_shift_mm(sim, vertices_of({model::FaceRegion::forehead}));
  EXPECT_GT(lower.z, 0.05f);
  EXPECT_GT(lower.z, forehead.z) << "forehead " << forehead.z << " mm";
  EXPECT_LT(glm::length(lower), 1.5f) << "under what lying down does";
}

TEST(HeadLoadsOnTheFace, TheTissueLagsATurnAndSettlesAfterIt) {
  SimulationOptions options;
  options.solver = Solver::projective;
  FaceSimulation sim(test::generic_tissue(), options);
  const std::size_t nose = model::generic_face().landmark_vertices[model::landmarks::kNoseTip];
  const float rest_x = model::generic_face().skin.positions[nose].x;
  // A quick shake: 0.5 rad in 0.2 s, minimum jerk (peaks at 72 rad/s^2).
  float earliest = 0.0f;
  for (int f = 1; f <= 6; ++f) {
    const float s = f / 6.0f;
    sim.set_head_pose({0.5f * (10 * s * s * s - 15 * s * s * s * s + 6 * s * s * s * s * s), 0.0f, 0.0f, {}});
    sim.step(kFrame);
    if (f <= 3) earliest = std::min(earliest, (sim.node_position(nose).x - rest_x) * kMm);
  }
  EXPECT_LT(earliest, -0.005f) << "the nose's tissue is left behind as the head speeds up";
  for (int f = 0; f < 90; ++f) sim.step(kFrame);
  EXPECT_NEAR((sim.node_position(nose).x - rest_x) * kMm, 0.0f, 0.01f) << "and comes back once it holds still";
}

TEST(HeadLoadsOnTheFace, ARestingFaceSleepsThroughSwayAndWakesForATilt) {
  SimulationOptions options;
  options.solver = Solver::projective;
  FaceSimulation sim(test::generic_tissue(), options);
  sim.step(kFrame);
  ASSERT_TRUE(sim.at_rest());
  // Two degrees of pitch at 0.3 Hz, as eye_head.cpp's noise sways a head.
  for (int f = 1; f <= 90; ++f) {
    sim.set_head_pose({0.0f, 0.035f * std::sin(2.0f * std::numbers::pi_v<float> * 0.3f * float(f * kFrame)), 0.0f, {}});
    sim.step(kFrame);
    ASSERT_TRUE(sim.at_rest()) << "frame " << f;
  }
  // Then the head bows 17 degrees in half a second.
  bool woke = false;
  for (int f = 1; f <= 15; ++f) {
    sim.set_head_pose({0.0f, -0.3f * f / 15.0f, 0.0f, {}});
    sim.step(kFrame);
    woke = woke || !sim.at_rest();
  }
  EXPECT_TRUE(woke);
}

TEST(HeadLoadsOnTheFace, AGlanceLetsTheFaceRest) {
  SimulationOptions options;
  options.solver = Solver::projective;
  FaceSimulation sim(test::generic_tissue(), options);
  sim.step(kFrame);
  // A gaze shift's turn: 0.6 rad in 0.4 s (peaks at 22 rad/s^2): its load
  // would move the skin by a tenth of a millimetre for a tenth of a second.
  for (int f = 1; f <= 12; ++f) {
    const float s = f / 12.0f;
    sim.set_head_pose({0.6f * (10 * s * s * s - 15 * s * s * s * s + 6 * s * s * s * s * s), 0.0f, 0.0f, {}});
    sim.step(kFrame);
    EXPECT_TRUE(sim.at_rest()) << "frame " << f;
  }
}

}  // namespace
}  // namespace fw::physics
