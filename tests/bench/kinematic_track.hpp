#pragma once
// The kinematic fallback of a room's face (server/simulation
// room_simulation.cpp, follow_kinematically): each AU approaches its target
// with the muscles' activation time constants, avatar/physics' defaults.
#include <cstddef>

#include "fw/physics/behaviour_corpus.hpp"
#include "fw/physics/face_simulation.hpp"
#include "fw/physics/muscle_activation.hpp"

namespace fw::bench {

class KinematicTrack {
 public:
  void follow(const physics::AuFrame& targets, double dt_s) {
    const physics::SimulationOptions muscles;
    const physics::ActivationRates rates =
        physics::activation_rates(muscles.activation_time_s, muscles.deactivation_time_s, static_cast<float>(dt_s));
    for (std::size_t c = 0; c < targets.size(); ++c) weights_[c] = physics::follow_activation(weights_[c], targets[c], rates);
  }
  const physics::AuFrame& weights() const { return weights_; }

 private:
  physics::AuFrame weights_{};
};

}  // namespace fw::bench
