#pragma once
// Action-unit targets of one moment: the type a lip-sync track yields, the
// same std::array as fw::behavior::AuTargets, so the room can play either.
#include <array>

#include "fw/codec/face_params.hpp"

namespace fw::speech {

/// Intensities in [0,1] in codec::kAuChannels order.
using AuTargets = std::array<float, codec::kAuChannelCount>;

}  // namespace fw::speech
