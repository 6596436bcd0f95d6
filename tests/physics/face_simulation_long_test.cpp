// Long runs of the physics face (label `slow`): a minute at full activation
// and a minute of activations switched on and off must not gain energy.
#include "fw/physics/face_simulation.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "fw/model/generic_face.hpp"
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

}  // namespace
}  // namespace fw::physics
