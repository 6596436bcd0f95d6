// The projective-dynamics solver beside the mass-spring one it stands in for
// where speed matters: the same settled shapes, the volumes each solver
// keeps, and one factorisation per tissue model.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "fw/model/landmark_template.hpp"
#include "fw/physics/face_simulation.hpp"
#include "generic_tissue.hpp"

namespace fw::physics {
namespace {

using UnitTargets = std::array<float, codec::kAuChannelCount>;
constexpr double kPdFrame = 1.0 / 30.0;
constexpr float kPdMm = model::kMillimetresPerUnit;

bool moves_the_jaw(int au) { return au == 26 || au == 27; }

UnitTargets unit_alone(int au) {
  UnitTargets t{};
  t[static_cast<std::size_t>(codec::au_channel(au, codec::is_bilateral(au) ? codec::AuSide::left : codec::AuSide::both))] = 1.0f;
  return t;
}

// The face once `au` at full strength has settled (asleep, or after 10 s).
FaceSimulation settled(Solver solver, int au, std::shared_ptr<const TissueModel> tissue = test::generic_tissue()) {
  SimulationOptions options;
  options.solver = solver;
  FaceSimulation sim(std::move(tissue), options);
  sim.set_action_units(unit_alone(au));
  for (int f = 0; f < 300 && !sim.at_rest(); ++f) sim.step(kPdFrame);
  return sim;
}

// Both solvers settle where the same forces balance: PD's springs follow the
// biphasic curve through the projection, its prisms the volume gradient.
// Measured RMS differences over the skin: at most 0.031 mm (AU 9 and 15,
// under 4 % of their travel), and 0.52 mm of the 17.1 mm of AU 27's open
// jaw, whose stretched lips are where the two volume treatments part most.
// AU 24 presses the lips onto their contact, resolved after each of
// mass-spring's seven sub-steps and after PD's one step: 0.084 mm of its
// 0.69 (12 %). The harder the press the more the two part there: 0.046 of
// 0.53 mm before the lips' own muscle pulled their skin as fully as its
// fascia (muscle_course.cpp).
TEST(ProjectiveDynamics, SettledActionUnitsHaveTheMassSpringShapes) {
  const auto& rest = model::generic_face().skin.positions;
  for (int au : codec::kActionUnits) {
    const FaceSimulation reference = settled(Solver::mass_spring, au), pd = settled(Solver::projective, au);
    EXPECT_TRUE(pd.at_rest()) << "AU " << au << " still moving after 10 s";
    const auto a = reference.surface(), b = pd.surface();
    double difference2 = 0.0, travel2 = 0.0;
    for (std::size_t v = 0; v < a.size(); ++v) {
      difference2 += glm::dot(a[v] - b[v], a[v] - b[v]);
      travel2 += glm::dot(a[v] - rest[v], a[v] - rest[v]);
    }
    const double rms_mm = std::sqrt(difference2 / double(a.size())) * kPdMm;
    const double travel_mm = std::sqrt(travel2 / double(a.size())) * kPdMm;
    EXPECT_LT(rms_mm, moves_the_jaw(au) ? 0.8 : au == 24 ? 0.1 : 0.06) << "AU " << au << " of " << travel_mm << " mm";
    EXPECT_LT(rms_mm, (moves_the_jaw(au) ? 0.05 : au == 24 ? 0.14 : 0.08) * travel_mm) << "AU " << au;
  }
}

class SettledVolumes : public ::testing::TestWithParam<Solver> {};
std::string settled_solver_name(const ::testing::TestParamInfo<Solver>& info) {
  return info.param == Solver::mass_spring ? "MassSpring" : info.param == Solver::pbd ? "Xpbd" : "Projective";
}
INSTANTIATE_TEST_SUITE_P(Solvers, SettledVolumes, ::testing::Values(Solver::mass_spring, Solver::pbd, Solver::projective),
                         settled_solver_name);

// A settled face's prisms against their rest volumes.
struct VolumeBand {
  float worst = 0.0f;       ///< the largest |V / V0 - 1|
  std::size_t outside = 0;  ///< prisms beyond 5 %
};
VolumeBand volume_band(const FaceSimulation& sim) {
  const TissueModel& m = sim.model();
  VolumeBand band;
  for (std::size_t e = 0; e < m.element_count(); ++e) {
    const float change = std::abs(sim.element_volume(e) / m.element_rest_volume[e] - 1.0f);
    band.worst = std::max(band.worst, change);
    band.outside += change > 0.05f;
  }
  return band;
}

// The volume bound: each prism within 5 % of its volume once a single unit
// at full strength has settled. It holds for most prisms, not all, in every
// solver: the thin lid and chin columns that a unit shears by more than
// their thickness, and under the jaw's units the prisms whose bone corners
// the jaw moves apart (README, "The volume requirement": what holds every
// prism locks the units). Asserted: the real 5 % bound for the share of
// prisms it holds for and each solver's measured worst, so that a change
// that folds more tissue fails. Measured, single units (worst unit) / AU
// 26-27, with the default bulk curve (1.5 times past 4 %):
//   mass-spring  worst 48.5 % (AU 6), 148 of 1610 outside (AU 6) / 79 %
//   projective   worst 48.7 % (AU 6), 146 of 1610 outside (AU 6) / 97 %
//   XPBD         worst 44.8 % (AU 6), 102 of 1610 outside (AU 6) / 78 %
// (with the linear term 55.7, 56.1 and 54.1 %; 157, 149 and 110 outside).
// The table the test prints gives every unit's worst prism and the prisms
// outside the band.
TEST_P(SettledVolumes, TheVolumeBoundHoldsForMostPrisms) {
  struct Levels {
    float within, single, jaw;
  };
  const Levels measured = GetParam() == Solver::mass_spring ? Levels{0.89f, 0.60f, 0.85f}
                          : GetParam() == Solver::pbd       ? Levels{0.92f, 0.58f, 0.85f}
                                                            : Levels{0.89f, 0.60f, 1.15f};
  float worst_single = 0.0f;
  for (int au : codec::kActionUnits) {
    const FaceSimulation sim = settled(GetParam(), au);
    const std::size_t prisms = sim.model().element_count();
    const VolumeBand band = volume_band(sim);
    std::printf("AU %2d: worst prism %5.1f %%, %3zu of %zu prisms beyond 5 %%%s\n", au, 100.0f * band.worst, band.outside,
                prisms, sim.at_rest() ? "" : " (still moving)");
    if (moves_the_jaw(au)) {
      EXPECT_LT(band.worst, measured.jaw) << "AU " << au;
      continue;
    }
    worst_single = std::max(worst_single, band.worst);
    EXPECT_LT(band.worst, measured.single) << "AU " << au;
    EXPECT_GE(float(prisms - band.outside), measured.within * float(prisms)) << "AU " << au << ": prisms within 5 %";
  }
  EXPECT_GT(worst_single, 0.05f) << "the 5 % requirement now holds for every prism: tighten this test to it";
}

double skin_travel_mm(const FaceSimulation& sim) {
  const auto& rest = model::generic_face().skin.positions;
  const auto now = sim.surface();
  double travel2 = 0.0;
  for (std::size_t v = 0; v < now.size(); ++v) travel2 += glm::dot(now[v] - rest[v], now[v] - rest[v]);
  return std::sqrt(travel2 / double(now.size())) * kPdMm;
}

// The bulk curve (on by default, tissue_model.cpp says why), at 1.5 times
// past a 4 % knee: it narrows the band (AU 6's worst prism 49 % instead of
// 56 %, XPBD 45 % instead of 54 %) without locking the tissue: a stiffer
// bulk term takes travel from the units whose tissue shears (a slope three
// times as stiff everywhere left AU 25 0.85 of its travel, AU 17 0.88; a
// hard band per prism AU 17 0.36), and each unit keeps at least 0.9 of the
// settled RMS travel it has with the linear term. Measured: AU 17 and 25
// 0.97, AU 15, 12 and 9 0.99 (XPBD 0.98-1.0); with the slope tripled past
// the knee AU 17 kept 0.91, quintupled 0.86.
TEST_P(SettledVolumes, TheBulkCurveNarrowsTheBandWithoutLockingTheUnits) {
  ASSERT_EQ(TissueMaterial::normal().volume_stiff_ratio, 1.5f) << "the default material's curve";
  TissueOptions linear;
  linear.material.volume_stiff_ratio = 1.0f;
  const auto& face = model::generic_face();
  const auto linear_tissue = build_tissue_model(face, face.action_units, linear);
  const auto curved_tissue = test::generic_tissue();
  const float linear_worst = volume_band(settled(GetParam(), 6, linear_tissue)).worst;
  const float curved_worst = volume_band(settled(GetParam(), 6, curved_tissue)).worst;
  std::printf("AU  6's worst prism: %.1f %% linear, %.1f %% with the curve\n", 100.0f * linear_worst,
              100.0f * curved_worst);
  EXPECT_LT(curved_worst, linear_worst - 0.05f) << "the curve narrows the band";
  for (int au : {17, 25, 15, 12, 9}) {
    const double kept =
        skin_travel_mm(settled(GetParam(), au, curved_tissue)) / skin_travel_mm(settled(GetParam(), au, linear_tissue));
    std::printf("AU %2d keeps %.3f of its travel\n", au, kept);
    EXPECT_GE(kept, 0.9) << "AU " << au;
  }
}

// Tissue on the jaw rides it: each node's bond to its bone (the material's
// bone_damping, as mass-spring has it) carries the lower lip with the
// closing mandible. 99 ms after an open jaw (AU 26) is let go, the lip is
// 7.0 mm further from rest than its bone (mass-spring 5.7); at one step a
// frame it was 8.7, and with Rayleigh damping alone, as before the bond,
// 11.4 mm behind.
TEST(ProjectiveDynamics, TissueOnTheJawKeepsUpWithIt) {
  SimulationOptions options;
  options.solver = Solver::projective;
  FaceSimulation sim(test::generic_tissue(), options);
  const TissueModel& m = sim.model();
  const std::size_t bone = kMovingLayerCount * m.vertex_count;
  // How far the lower lip's skin and its bone are below rest, mm.
  const auto lowered_mm = [&](std::size_t layer_start) {
    float sum = 0.0f;
    for (const auto& pair : m.lip_pairs) {
      const std::size_t node = layer_start + pair[1];
      sum += m.rest_y[node] - sim.node_position(node).y;
    }
    return sum / float(m.lip_pairs.size()) * kPdMm;
  };
  sim.set_action_units(unit_alone(26));
  for (int f = 0; f < 60; ++f) sim.step(kPdFrame);
  ASSERT_GT(lowered_mm(bone), 10.0f) << "the jaw is open";
  sim.set_action_units({});
  for (int f = 0; f < 3; ++f) sim.step(kPdFrame);
  const float behind = lowered_mm(0) - lowered_mm(bone);
  EXPECT_GT(behind, 0.0f) << "the lip trails its bone";
  EXPECT_LT(behind, 10.0f) << "the lip keeps up with its bone";
}

// One factorisation per model and step length (on a 2 % grid), made on
// first use and shared by every face of the model; a copied model (which may
// then be changed) starts without.
TEST(ProjectiveDynamics, OneFactorisationServesEveryFaceOfAModel) {
  const auto tissue = build_tissue_model(model::generic_face(), model::generic_face().action_units);
  SimulationOptions options;
  options.solver = Solver::projective;
  FaceSimulation a(tissue, options), b(tissue, options);
  EXPECT_EQ(tissue->projective_systems.size(), 0u) << "nothing is factored before a step";
  for (FaceSimulation* face : {&a, &b}) {
    face->set_action_units(unit_alone(12));
    face->step(kPdFrame);
  }
  EXPECT_EQ(a.substeps_for(kPdFrame), 2) << "a 30 Hz frame is two implicit steps";
  EXPECT_EQ(tissue->projective_systems.size(), 1u);
  EXPECT_GT(tissue->projective_systems.memory_bytes(), 0u);
  for (double jittered : {0.0334, 0.0332, 0.03335}) a.step(jittered);
  EXPECT_EQ(tissue->projective_systems.size(), 1u) << "frames 0.5 % long or short share the matrix";
  a.step(0.005);
  EXPECT_EQ(tissue->projective_systems.size(), 2u) << "another step length, another matrix";
  const TissueModel copy = *tissue;
  EXPECT_EQ(copy.projective_systems.size(), 0u);
}

}  // namespace
}  // namespace fw::physics
