#pragma once
// A face of a room as its viewers' streams are offered it each tick.
#include <cstdint>

#include "fw/codec/codec.hpp"
#include "fw/codec/face_params.hpp"

namespace fw::server {

class FaceEncoders;

struct AvatarFace {
  std::uint32_t id = 0;
  const codec::FaceParams* face = nullptr;
  /// The face as the encoders see it, offered this tick (face_sources.hpp);
  /// null: each encoder works it out from `face`.
  const codec::FaceSource* source = nullptr;
  /// The encoders its viewers share (shared_encoder.hpp), with `source`;
  /// null: each viewer encodes on its own.
  FaceEncoders* encoders = nullptr;
};

}  // namespace fw::server
