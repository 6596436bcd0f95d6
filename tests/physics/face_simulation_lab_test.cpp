// The face lab's API of FaceSimulation (face_simulation_lab.cpp) and the
// aged skin between normal() and loose() (aged_skin.cpp).
#include "fw/physics/face_simulation.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "fw/model/generic_face.hpp"
#include "fw/model/landmark_template.hpp"
#include "generic_tissue.hpp"

namespace fw::physics {
namespace {

using test::generic_tissue;
using AuTargets = std::array<float, codec::kAuChannelCount>;

void expect_same(const TissueMaterial& a, const TissueMaterial& b) {
  for (std::size_t k = 0; k < kSpringKindCount; ++k) {
    EXPECT_FLOAT_EQ(a.curves[k].stiffness, b.curves[k].stiffness) << "kind " << k;
    EXPECT_FLOAT_EQ(a.curves[k].residual_strain, b.curves[k].residual_strain) << "kind " << k;
    EXPECT_FLOAT_EQ(a.curves[k].compression_share, b.curves[k].compression_share) << "kind " << k;
    EXPECT_FLOAT_EQ(a.curves[k].knee_strain, b.curves[k].knee_strain) << "kind " << k;
    EXPECT_FLOAT_EQ(a.damping[k], b.damping[k]) << "kind " << k;
  }
  EXPECT_FLOAT_EQ(a.volume_stiffness, b.volume_stiffness);
}

TEST(AgedSkin, RunsFromNormalToLooseAndEachControlChangesItsOwnParameter) {
  expect_same(TissueMaterial::aged(0, 0), TissueMaterial::normal());
  expect_same(TissueMaterial::aged(1, 1), TissueMaterial::loose());
  expect_same(TissueMaterial::aged(-3, 7), TissueMaterial::aged(0, 1));  // clamped
  const auto skin = static_cast<std::size_t>(SpringKind::dermis);
  const auto muscle = static_cast<std::size_t>(SpringKind::column_muscle);
  const TissueMaterial normal = TissueMaterial::normal(), half_aged = TissueMaterial::aged(0.5f, 0);
  EXPECT_FLOAT_EQ(half_aged.curves[skin].stiffness, 0.75f * normal.curves[skin].stiffness) << "age softens";
  EXPECT_FLOAT_EQ(half_aged.curves[skin].residual_strain, 0.0f) << "age alone leaves the skin taut";
  EXPECT_FLOAT_EQ(half_aged.curves[muscle].stiffness, normal.curves[muscle].stiffness) << "the muscle layer stays";
  const TissueMaterial loose = TissueMaterial::aged(0, 0.5f);
  EXPECT_FLOAT_EQ(loose.curves[skin].stiffness, normal.curves[skin].stiffness) << "looseness alone keeps the slopes";
  EXPECT_FLOAT_EQ(loose.curves[skin].residual_strain, -0.025f);
  EXPECT_FLOAT_EQ(loose.curves[skin].compression_share, 0.5f) << "half as loose, half the resistance to compression";
  EXPECT_FLOAT_EQ(half_aged.curves[skin].compression_share, 1.0f) << "age alone keeps it";
}

TEST(FaceSimulationLab, AMuscleFloorDrivesTheMuscleOnTopOfTheActionUnits) {
  FaceSimulation sim(generic_tissue());
  const int zygomatic = muscle_index("zygomatic_major", true);
  ASSERT_GE(zygomatic, 0);
  std::array<float, kMuscleCount> floor{};
  floor[static_cast<std::size_t>(zygomatic)] = 0.5f;
  sim.set_muscle_floor(floor);
  EXPECT_FALSE(sim.at_rest()) << "a new floor wakes the face";
  for (int i = 0; i < 30; ++i) sim.step(1.0 / 30);
  EXPECT_NEAR(sim.muscle_activations()[static_cast<std::size_t>(zygomatic)], 0.5f, 0.01f);
  AuTargets au12{};
  au12[static_cast<std::size_t>(codec::au_channel(12, codec::AuSide::left))] = 1.0f;
  sim.set_action_units(au12);
  for (int i = 0; i < 30; ++i) sim.step(1.0 / 30);
  EXPECT_NEAR(sim.muscle_activations()[static_cast<std::size_t>(zygomatic)], 1.0f, 0.01f) << "the larger wins";
  sim.set_action_units(AuTargets{});
  for (int i = 0; i < 30; ++i) sim.step(1.0 / 30);
  EXPECT_NEAR(sim.muscle_activations()[static_cast<std::size_t>(zygomatic)], 0.5f, 0.01f) << "the floor holds";
  sim.set_muscle_floor({});
  for (int i = 0; i < 60; ++i) sim.step(1.0 / 30);
  EXPECT_LT(sim.muscle_activations()[static_cast<std::size_t>(zygomatic)], 0.01f);
}

// The face lab's oldest, loosest skin: a smile held a second and let go
// comes back. With every skin layer slack (tension only) nothing brought
// the skin back from where the pull left it: 2.5 mm off its rest 2.5 s
// later, a parted, crooked mouth.
TEST(FaceSimulationLab, AgedSkinLetGoComesBack) {
  TissueOptions aged;
  aged.material = TissueMaterial::aged(1, 1);
  SimulationOptions options;
  options.solver = Solver::projective;  // as rooms and previews step it
  FaceSimulation sim(generic_tissue(), options);
  sim.replace_model(build_tissue_model(model::generic_face(), model::generic_face().action_units, aged));
  for (int i = 0; i < 30; ++i) sim.step(1.0 / 30);
  const std::vector<glm::vec3> rest = sim.surface();
  std::array<float, kMuscleCount> floor{};
  floor[static_cast<std::size_t>(muscle_index("zygomatic_major", true))] = 1.0f;
  sim.set_muscle_floor(floor);
  for (int i = 0; i < 30; ++i) sim.step(1.0 / 30);
  const auto farthest_mm = [&] {
    float worst = 0.0f;
    const std::vector<glm::vec3> now = sim.surface();
    for (std::size_t v = 0; v < rest.size(); ++v) worst = std::max(worst, glm::distance(now[v], rest[v]));
    return worst * model::kMillimetresPerUnit;
  };
  EXPECT_GT(farthest_mm(), 9.0f) << "the loose skin follows the pull further than normal skin's 7.5 mm";
  sim.set_muscle_floor({});
  for (int i = 0; i < 75; ++i) sim.step(1.0 / 30);
  EXPECT_LT(farthest_mm(), 0.5f) << "2.5 s after the pull let go";
}

TEST(FaceSimulationLab, AnotherMaterialGoesOnFromTheShapeTheFaceHas) {
  FaceSimulation sim(generic_tissue());
  std::array<float, kMuscleCount> floor{};
  floor[static_cast<std::size_t>(muscle_index("zygomatic_major", true))] = 1.0f;
  sim.set_muscle_floor(floor);
  for (int i = 0; i < 10; ++i) sim.step(1.0 / 30);
  const std::vector<glm::vec3> before = sim.surface();
  TissueOptions old;
  old.material = TissueMaterial::aged(1, 0);
  sim.replace_model(build_tissue_model(model::generic_face(), model::generic_face().action_units, old));
  EXPECT_EQ(sim.surface(), before) << "replacing the model moves nothing by itself";
  EXPECT_FALSE(sim.at_rest());
  EXPECT_FLOAT_EQ(sim.model().material.curves[0].stiffness, old.material.curves[0].stiffness);
  EXPECT_NE(&sim.model(), generic_tissue().get()) << "the shared model is not changed";
  EXPECT_FLOAT_EQ(generic_tissue()->material.curves[0].stiffness, TissueMaterial::normal().curves[0].stiffness);
  for (int i = 0; i < 30; ++i) sim.step(1.0 / 30);
  for (const glm::vec3& p : sim.surface()) ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
}

}  // namespace
}  // namespace fw::physics
