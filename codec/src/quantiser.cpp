#include "quantiser.hpp"

#include "channel_table.hpp"

#include <cassert>
#include <cmath>

namespace fw::codec {
namespace {

// Fields after the action units, in channel order (const or not with P).
template <typename P>
auto tail_field(P& p, std::size_t i) -> decltype(&p.pallor) {
  decltype(&p.pallor) const fields[] = {&p.head_yaw_rad,           &p.head_pitch_rad,         &p.head_roll_rad,
                           &p.head_translation_mm[0], &p.head_translation_mm[1], &p.head_translation_mm[2],
                           &p.eye_left.yaw_rad,       &p.eye_left.pitch_rad,     &p.eye_right.yaw_rad,
                           &p.eye_right.pitch_rad,    &p.lid_left,               &p.lid_right,
                           &p.blush[0],               &p.blush[1],               &p.blush[2],
                           &p.blush[3],               &p.blush[4],               &p.pallor,
                           &p.corrective[0],          &p.corrective[1],          &p.corrective[2],
                           &p.corrective[3],          &p.corrective[4],          &p.corrective[5]};
  static_assert(sizeof fields / sizeof fields[0] == kChannelCount - kAuChannelCount);
  return fields[i];
}

}  // namespace

float channel_value(const FaceParams& params, std::size_t channel) {
  assert(channel < kChannelCount);
  if (channel < kAuChannelCount) return params.au[channel];
  return *tail_field(params, channel - kAuChannelCount);
}

void set_channel_value(FaceParams& params, std::size_t channel, float value) {
  assert(channel < kChannelCount);
  if (channel < kAuChannelCount) {
    params.au[channel] = value;
  } else {
    *tail_field(params, channel - kAuChannelCount) = value;
  }
}

double to_steps(float value, std::size_t channel) {
  const ChannelInfo& info = channel_table()[channel];
  if (std::isnan(value)) return 0.0;
  const double steps = static_cast<double>(value) / static_cast<double>(info.step);
  if (steps < info.min_q) return info.min_q;
  if (steps > info.max_q) return info.max_q;
  return steps;
}

std::int32_t clamp_coded(std::int64_t q, std::size_t channel) {
  const CodedRange range = coded_range(channel);
  if (q < range.min) return range.min;
  if (q > range.max) return range.max;
  return static_cast<std::int32_t>(q);
}

QuantisedParams quantise(const FaceParams& params) {
  QuantisedParams q{};
  for (std::size_t c = 0; c < kChannelCount; ++c) q[c] = round_nearest(to_steps(channel_value(params, c), c));
  return q;
}

FaceParams dequantise(const QuantisedParams& q) {
  FaceParams params;
  const auto& table = channel_table();
  for (std::size_t c = 0; c < kChannelCount; ++c) set_channel_value(params, c, static_cast<float>(q[c]) * table[c].step);
  return params;
}

}  // namespace fw::codec
