// Long runs of the physics face (label `slow`): a minute at full activation,
// a minute of activations switched on and off and a minute of random
// targets must not gain energy.
#include "fw/physics/face_simulation.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "fw/model/generic_face.hpp"
#include "fw/model/landmark_template.hpp"
#include "generic_tissue.hpp"

namespace fw::physics {
namespace {

constexpr double kFrame = 1.0 / 30.0;

using test::generic_tissue;

std::string solver_name(const ::testing::TestParamInfo<Solver>& info) {
  switch (info.param) {
    case Solver::mass_spring: return "MassSpring";
    case Solver::pbd: return "Pbd";
    case Solver::projective: return "Projective";
  }
  return "Unknown";
}

class FaceSimulationLong : public ::testing::TestWithParam<Solver> {};
INSTANTIATE_TEST_SUITE_P(Solvers, FaceSimulationLong, ::testing::Values(Solver::mass_spring, Solver::pbd, Solver::projective),
                         solver_name);

float max_displacement(const FaceSimulation& sim) {
  float worst = 0.0f;
  const TissueModel& m = sim.model();
  for (std::size_t i = 0; i < m.moving_node_count; ++i) {
    const glm::vec3 p = sim.node_position(i);
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return INFINITY;
    worst = std::max(worst, glm::length(p - glm::vec3(m.rest_x[i], m.rest_y[i], m.rest_z[i])));
  }
  return worst;
}

// Every unit at intensity 1 for 60 s: the face settles and stays settled.
// The targets flicker between 1 and 0.999 so that the face never sleeps.
TEST_P(FaceSimulationLong, NoEnergyGrowthOver60SecondsAtFullActivation) {
  SimulationOptions options;
  options.solver = GetParam();
  FaceSimulation sim(generic_tissue(), options);
  std::array<float, codec::kAuChannelCount> all{}, almost{};
  all.fill(1.0f);
  almost.fill(0.999f);
  double first_second_peak = 0.0, later_peak = 0.0;
  for (int f = 0; f < 60 * 30; ++f) {
    sim.set_action_units(f % 2 ? almost : all);
    ASSERT_FALSE(sim.at_rest());
    sim.step(kFrame);
    const double energy = sim.kinetic_energy();
    ASSERT_TRUE(std::isfinite(energy)) << "frame " << f;
    if (f < 30) first_second_peak = std::max(first_second_peak, energy);
    if (f >= 150) later_peak = std::max(later_peak, energy);
  }
  // The chin travels 0.9 units (57 mm) with the jaw wide open; nothing more.
  EXPECT_LT(max_displacement(sim), 1.2f);
  EXPECT_LT(later_peak, 1e-2 * first_second_peak) << "after 5 s the face only follows the flicker";
}

// Activations switched fully on and off every half second for 60 s: the
// energy each cycle brings must not build up.
TEST_P(FaceSimulationLong, NoEnergyGrowthOver60SecondsOfSwitchedActivation) {
  SimulationOptions options;
  options.solver = GetParam();
  FaceSimulation sim(generic_tissue(), options);
  std::array<float, codec::kAuChannelCount> all{}, none{};
  all.fill(1.0f);
  double early_peak = 0.0, late_peak = 0.0;
  for (int f = 0; f < 60 * 30; ++f) {
    if (f % 15 == 0) sim.set_action_units((f / 15) % 2 == 0 ? all : none);
    sim.step(kFrame);
    const double energy = sim.kinetic_energy();
    ASSERT_TRUE(std::isfinite(energy)) << "frame " << f;
    if (f < 10 * 30) early_peak = std::max(early_peak, energy);
    if (f >= 50 * 30) late_peak = std::max(late_peak, energy);
  }
  EXPECT_LE(late_peak, 1.05 * early_peak);
  EXPECT_LT(max_displacement(sim), 1.2f);
}

// A minute of random targets at 30 Hz frames, each unit jumping to a new
// intensity every 0.1-1 s, then ten seconds of none: the projective solver
// takes each frame as two implicit steps, with no speed limit, no drag of
// the world and no extra mass; the others take their sub-steps. Every
// solver must stay finite, its kinetic energy under its measured peak with
// a margin (the jaw's jumps make it: 1000-1870 measured), never move further
// than the jaw carries the chin, and come back to rest: a solver that gains
// energy from its steps does not.
TEST_P(FaceSimulationLong, StableOverAMinuteOfRandomTargetsAtFrameSteps) {
  SimulationOptions options;
  options.solver = GetParam();
  FaceSimulation sim(generic_tissue(), options);
  if (GetParam() == Solver::projective) {
    EXPECT_EQ(sim.substeps_for(kFrame), 2) << "two implicit steps per frame";
  }
  std::uint64_t state = 12345;
  auto uniform = [&] {  // xorshift64*: a fixed sequence
    state ^= state >> 12, state ^= state << 25, state ^= state >> 27;
    return double((state * 0x2545F4914F6CDD1DULL) >> 11) / double(1ULL << 53);
  };
  std::array<float, codec::kAuChannelCount> targets{};
  std::array<int, codec::kAuChannelCount> next_change{};
  double peak = 0.0;
  float farthest = 0.0f;
  for (int f = 0; f < 60 * 30; ++f) {
    for (std::size_t c = 0; c < targets.size(); ++c)
      if (f >= next_change[c]) {
        targets[c] = uniform() < 0.5 ? 0.0f : static_cast<float>(uniform());
        next_change[c] = f + 3 + static_cast<int>(uniform() * 27.0);
      }
    sim.set_action_units(targets);
    sim.step(kFrame);
    const double energy = sim.kinetic_energy();
    ASSERT_TRUE(std::isfinite(energy)) << "frame " << f;
    peak = std::max(peak, energy);
    if (f % 30 == 0) farthest = std::max(farthest, max_displacement(sim));
  }
  EXPECT_LT(peak, 4000.0);
  EXPECT_LT(farthest, 1.2f);
  sim.set_action_units({});
  for (int f = 0; f < 10 * 30; ++f) sim.step(kFrame);
  EXPECT_LT(sim.kinetic_energy(), 1e-6 * peak);
  EXPECT_LT(max_displacement(sim) * model::kMillimetresPerUnit, 0.05f) << "back at neutral";
}

// Steps of a tenth of a second with random targets, no speed limit and
// nothing added to the masses: XPBD takes each as one sub-step, projective
// dynamics as six implicit steps (its longest is 17.5 ms, for its
// accuracy: projective_dynamics.hpp), mass-spring as sub-steps at its own
// stable bound. Every
// solver must stay finite, never move further than the jaw carries the
// chin, gain no energy over the run (the last ten seconds' peak no higher
// than the first ten's) and come back to rest at neutral.
TEST_P(FaceSimulationLong, StableUnderLargeStepsWithNoClamp) {
  constexpr double kLargeStep = 0.1;
  SimulationOptions options;
  options.solver = GetParam();
  options.max_substep_s = kLargeStep;  // mass-spring: its own bound is shorter
  options.xpbd_substep_s = kLargeStep;
  FaceSimulation sim(generic_tissue(), options);
  if (GetParam() == Solver::pbd) {
    EXPECT_EQ(sim.substeps_for(kLargeStep), 1);
  }
  if (GetParam() == Solver::mass_spring) {
    EXPECT_EQ(sim.substeps_for(kLargeStep), static_cast<int>(std::ceil(kLargeStep / sim.model().stable_substep_s)));
  }
  std::uint64_t state = 777;
  auto uniform = [&] {  // xorshift64*: a fixed sequence
    state ^= state >> 12, state ^= state << 25, state ^= state >> 27;
    return double((state * 0x2545F4914F6CDD1DULL) >> 11) / double(1ULL << 53);
  };
  double early_peak = 0.0, late_peak = 0.0;
  float farthest = 0.0f;
  constexpr int kSteps = 300;  // 30 s
  for (int i = 0; i < kSteps; ++i) {
    std::array<float, codec::kAuChannelCount> targets{};
    for (float& t : targets) t = uniform() < 0.5 ? 0.0f : static_cast<float>(uniform());
    sim.set_action_units(targets);
    sim.step(kLargeStep);
    const double energy = sim.kinetic_energy();
    ASSERT_TRUE(std::isfinite(energy)) << "step " << i;
    if (i < 100) early_peak = std::max(early_peak, energy);
    if (i >= kSteps - 100) late_peak = std::max(late_peak, energy);
    farthest = std::max(farthest, max_displacement(sim));
  }
  EXPECT_LT(farthest, 1.2f);
  EXPECT_LE(late_peak, early_peak) << "energy grew";
  sim.set_action_units({});
  for (int i = 0; i < 100; ++i) sim.step(kLargeStep);
  EXPECT_LT(sim.kinetic_energy(), 1e-6 * early_peak);
  EXPECT_LT(max_displacement(sim) * model::kMillimetresPerUnit, 0.05f) << "back at neutral";
}

}  // namespace
}  // namespace fw::physics
