#include "reconstruction.hpp"

#include <algorithm>

#include "channel_table.hpp"

namespace fw::codec {

void Reconstruction::reset() { channels_ = {}; }

void Reconstruction::advance(std::uint32_t ticks) {
  // Only min(age, limit) matters, so ages stop there (and never overflow).
  for (Channel& ch : channels_)
    ch.age = static_cast<std::uint8_t>(std::min<std::uint64_t>(std::uint64_t{ch.age} + ticks, max_extrapolation_ticks_));
}

std::int64_t Reconstruction::glide(const Channel& ch, std::int64_t ticks) {
  // Tick by tick (at most 255 ticks): the exact integer recurrence of the format.
  std::int64_t v = ch.value;
  std::int64_t w = ch.velocity;
  for (std::int64_t i = 0; i < ticks && w != 0; ++i) {
    v += w;
    w = damp(w, ch.damping);
  }
  return v;
}

ChannelValues Reconstruction::shown_all(std::uint32_t extra_ticks) const {
  ChannelValues q{};
  for (std::size_t c = 0; c < kChannelCount; ++c) q[c] = shown_after(c, extra_ticks);
  return q;
}

void Reconstruction::set(std::size_t c, std::int32_t q, std::int32_t velocity_sub_steps, int damping) {
  channels_[c] = {q * kSubSteps, velocity_sub_steps, static_cast<std::uint8_t>(damping), 0};
}

void Reconstruction::freeze() {
  for (std::size_t c = 0; c < kChannelCount; ++c) set(c, shown(c), 0);
}

}  // namespace fw::codec
