#pragma once
// What encoder and decoder carry from one frame to the next, identically:
// the reconstruction, the adaptive models and the quality level in force.
#include "frame_models.hpp"
#include "reconstruction.hpp"

namespace fw::codec {

struct CodingState {
  explicit CodingState(std::uint8_t max_extrapolation_ticks) : reconstruction(max_extrapolation_ticks) {}

  Reconstruction reconstruction;
  FrameModels models;
  int level = 0;
};

}  // namespace fw::codec
