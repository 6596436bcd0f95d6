#pragma once
// The kinematic fallback of a room's face (server/simulation
// room_simulation.cpp, follow_kinematically): each AU approaches its target
// with the muscles' activation time constants, avatar/physics' defaults.
#include <cmath>
#include <cstddef>

#include "fw/physics/behaviour_corpus.hpp"
#include "fw/physics/face_simulation.hpp"

namespace fw::bench {

class KinematicTrack {
 public:
  void follow(const physics::AuFrame& targets, double dt_s) {
    const physics::SimulationOptions muscles;
    for (std::size_t c = 0; c < targets.size(); ++c) {
      const double tau = targets[c] > weights_[c] ? muscles.activation_time_s : muscles.deactivation_time_s;
      weights_[c] += static_cast<float>((1.0 - std::exp(-dt_s / tau)) * (targets[c] - weights_[c]));
    }
  }
  const physics::AuFrame& weights() const { return weights_; }

 private:
  physics::AuFrame weights_{};
};

}  // namespace fw::bench
