// Every avatar its own face (avatar_tissue.hpp): fitted faces simulated on
// their own rest shapes, sharing the generic face's projective
// factorisation and its batched solves, with the muscles of each person.
#include "fw/physics/avatar_tissue.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "fw/model/landmark_template.hpp"
#include "fw/physics/face_pool.hpp"
#include "fw/physics/face_simulation.hpp"
#include "fw/physics/muscle_variation.hpp"

namespace fw::physics {
namespace avatar_tissue_test {  // named: the tests are built as one unity file

using Targets = std::array<float, codec::kAuChannelCount>;
constexpr double kFrame = 1.0 / 30.0;

// Two people: a wide, short face and a narrow, long one.
model::AvatarModel fitted(float wide, float tall, float lean) {
  std::vector<glm::vec2> xy;
  for (const glm::vec3& p : model::generic_face().skin.positions) xy.emplace_back(wide * p.x + lean * p.y, tall * p.y);
  return model::make_avatar_model(model::generic_face(), xy);
}
const model::AvatarModel& wide_face() {
  static const auto avatar = fitted(1.1f, 0.93f, 0.02f);
  return avatar;
}
const model::AvatarModel& long_face() {
  static const auto avatar = fitted(0.92f, 1.08f, -0.01f);
  return avatar;
}

Targets smile_and_open() {
  Targets t{};
  t[codec::au_channel(12, codec::AuSide::left)] = 1.0f;
  t[codec::au_channel(12, codec::AuSide::right)] = 0.8f;
  t[codec::au_channel(27, codec::AuSide::both)] = 0.6f;
  return t;
}

SimulationOptions projective() {
  SimulationOptions o;
  o.solver = Solver::projective;
  return o;
}

// Skin displacement from the face's own rest shape, model units, per vertex.
std::vector<glm::vec3> displacement(const FaceSimulation& sim) {
  std::vector<glm::vec3> out;
  const TissueModel& m = sim.model();
  for (std::size_t v = 0; v < m.vertex_count; ++v)
    out.push_back(sim.node_position(v) - glm::vec3(m.rest_x[v], m.rest_y[v], m.rest_z[v]));
  return out;
}

double rms_mm(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += glm::dot(a[i] - b[i], a[i] - b[i]);
  return std::sqrt(sum / double(a.size())) * model::kMillimetresPerUnit;
}

void run(FaceSimulation& sim, const Targets& targets, int frames) {
  sim.set_action_units(targets);
  for (int f = 0; f < frames; ++f) sim.step(kFrame);
}

TEST(AvatarTissue, AFittedFaceKeepsTheGenericTopologyAndSharesItsFactorisation) {
  const auto generic = generic_tissue_model();
  const auto wide = build_avatar_tissue_model(wide_face(), generic);
  ASSERT_TRUE(wide->projective_reference);
  EXPECT_EQ(wide->projective_reference.get(), generic.get());
  EXPECT_TRUE(same_topology_and_material(*wide, *generic));
  // Its own rest shape: the fit's skin, not the generic one.
  double moved = 0.0;
  for (std::size_t v = 0; v < wide->vertex_count; ++v)
    moved = std::max(moved, double(std::abs(wide->rest_x[v] - generic->rest_x[v])));
  EXPECT_GT(moved * model::kMillimetresPerUnit, 3.0);
  // Another material cannot share the matrix: it factors its own.
  TissueOptions aged;
  aged.material = TissueMaterial::aged(1.0f, 1.0f);
  EXPECT_FALSE(build_avatar_tissue_model(wide_face(), generic, aged)->projective_reference);
}

// The fitted rest shape is the equilibrium: a face woken with no pull to
// speak of does not move, with the shared factorisation or its own.
TEST(AvatarTissue, AFittedFaceDoesNotMoveAtRest) {
  for (const auto* avatar : {&wide_face(), &long_face()}) {
    FaceSimulation sim(build_avatar_tissue_model(*avatar, generic_tissue_model()), projective());
    Targets whisper{};
    whisper[codec::au_channel(12, codec::AuSide::left)] = 1e-6f;
    run(sim, whisper, 60);
    const auto d = displacement(sim);
    EXPECT_LT(rms_mm(d, std::vector<glm::vec3>(d.size(), glm::vec3(0.0f))), 1e-3);
    const FaceMeasurement m = sim.measure();
    for (const float w : m.action_units) EXPECT_LT(w, 1e-3f);
    EXPECT_LT(m.residual_rms_mm, 1e-3f);
  }
}

// Two people, the same targets: two surfaces, each measured against its own morphs.
TEST(AvatarTissue, DifferentFacesGiveDifferentSurfacesForTheSameTargets) {
  const auto generic = generic_tissue_model();
  FaceSimulation wide(build_avatar_tissue_model(wide_face(), generic), projective());
  FaceSimulation lean(build_avatar_tissue_model(long_face(), generic), projective());
  run(wide, smile_and_open(), 90);
  run(lean, smile_and_open(), 90);
  const double apart = rms_mm(displacement(wide), displacement(lean));
  std::printf("the two faces' displacements differ by %.2f mm RMS\n", apart);
  EXPECT_GT(apart, 0.1);
  // Each is the smile on its own face: its own morphs explain it.
  for (FaceSimulation* sim : {&wide, &lean}) {
    const FaceMeasurement m = sim->measure();
    EXPECT_GT(m.action_units[codec::au_channel(12, codec::AuSide::left)], 0.4f);
    EXPECT_LT(m.residual_rms_mm, 1.5f);
  }
}

// The shared factorisation holds the generic face's prism weights; the
// fitted face's own would differ a little. What that does to the skin:
TEST(AvatarTissue, TheSharedFactorisationStaysCloseToTheFacesOwn) {
  for (const auto* avatar : {&wide_face(), &long_face()}) {
    FaceSimulation shared(build_avatar_tissue_model(*avatar, generic_tissue_model()), projective());
    FaceSimulation own(build_avatar_tissue_model(*avatar, nullptr), projective());
    ASSERT_FALSE(own.model().projective_reference);
    double worst = 0.0, travel = 0.0;
    for (int f = 0; f < 90; ++f) {
      for (FaceSimulation* sim : {&shared, &own}) run(*sim, smile_and_open(), 1);
      worst = std::max(worst, rms_mm(displacement(shared), displacement(own)));
    }
    const auto d = displacement(own);
    travel = rms_mm(d, std::vector<glm::vec3>(d.size(), glm::vec3(0.0f)));
    std::printf("shared against own factorisation: %.4f mm RMS at worst over 3 s, of %.2f mm RMS travel\n", worst,
                travel);
    EXPECT_LT(worst, 0.05 * travel);
    EXPECT_LT(worst, 0.1);
  }
}

// Faces of different avatars share one batched solve, and a face steps
// alike in a batch and alone (every lane width gives the same bits).
TEST(AvatarTissue, FacesOfDifferentAvatarsBatchTogether) {
  const auto generic = generic_tissue_model();
  const auto wide = build_avatar_tissue_model(wide_face(), generic);
  const auto lean = build_avatar_tissue_model(long_face(), generic);
  std::vector<FaceSimulation> batch, alone;
  for (int i = 0; i < 12; ++i) {
    SimulationOptions o = projective();
    o.seed = std::uint64_t(i);
    o.individual_variation = 1.0f;
    o.course_variation = 1.0f;  // every face its own courses, one factorisation
    const auto& model = i % 3 == 0 ? generic : i % 3 == 1 ? wide : lean;
    batch.emplace_back(model, o);
    alone.emplace_back(model, o);
  }
  FacePool pool(2);
  for (int f = 0; f < 20; ++f) {
    for (std::size_t i = 0; i < batch.size(); ++i) {
      batch[i].set_action_units(smile_and_open());
      alone[i].set_action_units(smile_and_open());
      alone[i].step(kFrame);
    }
    pool.step_all(batch, kFrame);
  }
  for (std::size_t i = 0; i < batch.size(); ++i)
    for (std::size_t n = 0; n < batch[i].model().node_count; ++n)
      ASSERT_EQ(batch[i].node_position(n), alone[i].node_position(n)) << "face " << i << " node " << n;
  // One factorisation, the generic face's, for all three faces' models.
  EXPECT_EQ(wide->projective_systems.size(), 1u);
  EXPECT_EQ(lean->projective_systems.size(), 1u);
  EXPECT_EQ(generic->projective_systems.size(), 1u);
}

// A batch's local step runs across its faces, a lane each, padded to 2, 4,
// 8 or 16 lanes: whatever its width, and whichever models share it, each
// face gets the bits it gets stepped alone.
TEST(AvatarTissue, EveryBatchWidthGivesEachFaceItsOwnBits) {
  const auto generic = generic_tissue_model();
  const auto wide = build_avatar_tissue_model(wide_face(), generic);
  const auto lean = build_avatar_tissue_model(long_face(), generic);
  FacePool pool(1);
  for (std::size_t width : {2u, 3u, 5u, 8u, 9u, 16u}) {
    std::vector<FaceSimulation> batch, alone;
    for (std::size_t i = 0; i < width; ++i) {
      SimulationOptions o = projective();
      o.seed = i;
      o.individual_variation = 1.0f;
      o.course_variation = 1.0f;
      const auto& model = i % 3 == 0 ? lean : i % 3 == 1 ? generic : wide;
      batch.emplace_back(model, o);
      alone.emplace_back(model, o);
    }
    for (int f = 0; f < 6; ++f) {
      for (std::size_t i = 0; i < width; ++i) {
        batch[i].set_action_units(smile_and_open());
        alone[i].set_action_units(smile_and_open());
        alone[i].step(kFrame);
      }
      pool.step_all(batch, kFrame);
    }
    for (std::size_t i = 0; i < width; ++i)
      for (std::size_t n = 0; n < batch[i].model().node_count; ++n)
        ASSERT_EQ(batch[i].node_position(n), alone[i].node_position(n)) << width << " faces, face " << i << " node " << n;
  }
}

// The room's switch: a face that began as the generic face takes its own
// model while it smiles, and what it shows does not jump.
TEST(AvatarTissue, ReplacingTheGenericFaceWithTheAvatarsOwnDoesNotJump) {
  FaceSimulation sim(generic_tissue_model(), projective());
  run(sim, smile_and_open(), 45);
  const FaceMeasurement before = sim.measure();
  const auto moved = displacement(sim);
  sim.replace_model(build_avatar_tissue_model(wide_face(), generic_tissue_model()));
  // Every free node keeps its displacement; the held outline is where the
  // new face's jaw holds it (its jaw takes other columns).
  const auto now = displacement(sim);
  for (std::size_t v = 0; v < now.size(); ++v) {
    if (sim.model().inverse_mass[v] != 0.0f) {
      EXPECT_LT(glm::length(now[v] - moved[v]), 1e-6f) << "vertex " << v;
    }
  }
  EXPECT_LT(rms_mm(now, moved), 0.5);
  // The weights are measured against other morphs now (the avatar's own):
  // they move by up to 0.36 (AU 17's, which on the open jaw shares the
  // lower lip's travel with AU 27 and, since the lips meet, stops at their
  // contact), which the room blends over RoomSimulation::kOwnFaceBlendS.
  const FaceMeasurement after = sim.measure();
  for (std::size_t c = 0; c < before.action_units.size(); ++c)
    EXPECT_NEAR(after.action_units[c], before.action_units[c], 0.4f) << "channel " << c;
  run(sim, smile_and_open(), 30);
  const FaceMeasurement later = sim.measure();
  EXPECT_NEAR(later.action_units[codec::au_channel(12, codec::AuSide::left)],
              before.action_units[codec::au_channel(12, codec::AuSide::left)], 0.15f);
  // And at rest on its own face again once the targets go.
  run(sim, Targets{}, 150);
  const auto d = displacement(sim);
  EXPECT_LT(rms_mm(d, std::vector<glm::vec3>(d.size(), glm::vec3(0.0f))), 0.02);
}

TEST(AvatarTissue, BuildTimeAndMemoryPerAvatar) {
  const auto generic = generic_tissue_model();
  const auto start = std::chrono::steady_clock::now();
  const auto wide = build_avatar_tissue_model(wide_face(), generic);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  FaceSimulation sim(wide, projective());
  run(sim, smile_and_open(), 2);
  const std::size_t bytes = wide->memory_bytes() + wide->projective_systems.memory_bytes();
  std::printf("an avatar's tissue model: %.1f ms to build, %zu KB with its constraints (the shared factor %zu KB)\n", ms,
              bytes / 1024, generic->projective_systems.memory_bytes() / 1024);
  EXPECT_LT(bytes, 2u << 20);
}

TEST(MuscleVariation, IsDeterministicWithinItsRangeAndDiffersBetweenPeople) {
  EXPECT_EQ(muscle_strength_factors(42), muscle_strength_factors(42));
  EXPECT_NE(muscle_strength_factors(42), muscle_strength_factors(43));
  EXPECT_EQ(variation_seed("0123456789abcdef0123456789abcdef"), variation_seed("0123456789abcdef0123456789abcdef"));
  EXPECT_NE(variation_seed("0123456789abcdef0123456789abcdef"), variation_seed("0123456789abcdef0123456789abcdee"));
  for (const float f : muscle_strength_factors(7, 0.0f)) EXPECT_EQ(f, 1.0f);
  double spread = 0.0, asymmetry = 0.0;
  int samples = 0;
  for (std::uint64_t seed = 0; seed < 2000; ++seed) {
    const auto factor = muscle_strength_factors(seed);
    for (std::size_t pair = 0; pair < kMusclesPerSide; ++pair) {
      const float k = universally_present(pair) ? 1.0f : kVariableMuscleFactor;
      const float bound = k * (kPairVariation + kSideVariation);
      for (std::size_t side = 0; side < 2; ++side) {
        ASSERT_GE(factor[2 * pair + side], 1.0f - bound - 1e-6f);
        ASSERT_LE(factor[2 * pair + side], 1.0f + bound + 1e-6f);
      }
      if (!universally_present(pair)) continue;
      spread = std::max(spread, double(std::abs(factor[2 * pair] - 1.0f)));
      asymmetry = std::max(asymmetry, double(std::abs(factor[2 * pair] - factor[2 * pair + 1])));
      ++samples;
    }
  }
  // Over 2000 people the range is used, and the sides stay close.
  EXPECT_GT(spread, 0.9 * (kPairVariation + kSideVariation));
  EXPECT_LE(asymmetry, 2.0 * kSideVariation + 1e-6);
  EXPECT_GT(samples, 0);
  EXPECT_FALSE(universally_present(static_cast<std::size_t>(muscle_index("risorius", true) / 2)));
  EXPECT_TRUE(universally_present(static_cast<std::size_t>(muscle_index("zygomatic_major", true) / 2)));
}

}  // namespace avatar_tissue_test
}  // namespace fw::physics
