#pragma once
// FaceParams as JavaScript hands them over: 53 floats in the codec's channel
// order (codec/FORMAT.md, "Channels"; web/codec/quantiser.js's dequantise):
// the 29 AU channels, head yaw, pitch, roll, translation x, y, z (mm), left
// eye yaw, pitch, right eye yaw, pitch, lid left, right, 5 blush, pallor, and
// the 6 corrective weights last.
// web/engine/face_params_floats.js writes them.
#include <cstddef>

#include "fw/codec/face_params.hpp"

namespace fw::wasm {

inline constexpr std::size_t kFaceParamsFloats = codec::kAuChannelCount + 18 + codec::kCorrectiveCount;

inline codec::FaceParams face_params_from_floats(const float* f) {
  codec::FaceParams p;
  std::size_t i = 0;
  for (float& a : p.au) a = f[i++];
  p.head_yaw_rad = f[i++];
  p.head_pitch_rad = f[i++];
  p.head_roll_rad = f[i++];
  for (float& t : p.head_translation_mm) t = f[i++];
  p.eye_left.yaw_rad = f[i++];
  p.eye_left.pitch_rad = f[i++];
  p.eye_right.yaw_rad = f[i++];
  p.eye_right.pitch_rad = f[i++];
  p.lid_left = f[i++];
  p.lid_right = f[i++];
  for (float& b : p.blush) b = f[i++];
  p.pallor = f[i++];
  for (float& w : p.corrective) w = f[i++];
  return p;
}

}  // namespace fw::wasm
