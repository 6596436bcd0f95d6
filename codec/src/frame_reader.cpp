#include "frame_reader.hpp"

#include <bit>
#include <cstdlib>

#include "channel_table.hpp"
#include "integer_coding.hpp"
#include "quantiser.hpp"
#include "range_decoder.hpp"

namespace fw::codec {
namespace {

// The velocity and damping of channel `c` after its update (the mirror of
// write_motion): a velocity beyond the channel's limit fails the frame.
std::int32_t read_motion(RangeDecoder& rc, FrameModels& m, std::size_t c, std::size_t g, int shift,
                         bool from_partner, std::int64_t predicted, int partner_damping, int& damping) {
  const std::int64_t unit = std::int64_t{kVelocityUnitSubSteps} << shift;
  const std::int64_t dv = decode_signed(rc, m.velocity[g][from_partner ? 1 : 0]);
  std::int64_t velocity = predicted + dv * unit;
  if (std::llabs(velocity) > max_velocity(c)) {
    rc.fail(DecodeError::value_out_of_range);
    velocity = 0;
  }
  damping = 0;
  if (velocity != 0)
    damping = decode_damping(rc, m.damping[g][from_partner ? static_cast<std::size_t>(1 + partner_damping) : 0]);
  return static_cast<std::int32_t>(velocity);
}

void read_key(CodingState& state, RangeDecoder& rc) {
  FrameModels& m = state.models;
  state.level = static_cast<int>(rc.decode_raw(kLevelBits));
  const auto& table = channel_table();
  ChannelValues q_new{};
  std::array<std::int32_t, kChannelCount> u_new{};
  std::array<int, kChannelCount> damping_new{};
  for (std::size_t c = 0; c < kChannelCount; ++c) {
    const ChannelInfo& info = table[c];
    const std::size_t g = group_index(info.group);
    const int s = group_shift(state.level, g);
    std::int32_t q = 0;
    bool coded = false;
    if (info.partner >= 0 && rc.decode(m.key_same_as_partner[g]) == 1) {
      q = q_new[static_cast<std::size_t>(info.partner)];
      coded = true;
    }
    if (!coded && rc.decode(m.key_nonzero[g]) == 1) {
      const std::int32_t k_min = round_to_units(coded_range(c).min, s);
      const std::int32_t k_max = round_to_units(coded_range(c).max, s);
      const std::uint32_t offset = rc.decode_raw(std::bit_width(static_cast<std::uint32_t>(k_max - k_min)));
      if (offset > static_cast<std::uint32_t>(k_max - k_min)) rc.fail(DecodeError::value_out_of_range);
      q = clamp_coded((std::int64_t{k_min} + offset) * (std::int64_t{1} << s), c);
    }
    const bool from_partner = info.partner >= 0;
    const auto p = static_cast<std::size_t>(from_partner ? info.partner : 0);
    q_new[c] = q;
    u_new[c] = read_motion(rc, m, c, g, s, from_partner, from_partner ? u_new[p] : 0,
                           from_partner ? damping_new[p] : 0, damping_new[c]);
    state.reconstruction.set(c, q, u_new[c], damping_new[c]);
  }
}

void read_predicted(CodingState& state, RangeDecoder& rc) {
  FrameModels& m = state.models;
  Reconstruction& rec = state.reconstruction;
  if (rc.decode(m.level_changed) == 1) state.level = static_cast<int>(rc.decode_raw(kLevelBits));
  const auto& table = channel_table();
  std::array<bool, kChannelCount> updated_now{};
  std::array<std::int32_t, kChannelCount> residual{};
  std::array<std::int32_t, kChannelCount> u_new{};
  std::array<int, kChannelCount> damping_new{};
  for (std::size_t g = 0; g < kChannelGroupCount; ++g) {
    const bool any = rc.decode(m.group_updated[g][m.group_updated_last[g] ? 1 : 0]) == 1;
    m.group_updated_last[g] = any;
    if (!any) continue;
    const GroupSpan span = group_spans()[g];
    const int s = group_shift(state.level, g);
    for (std::size_t c = span.first; c < span.first + span.count; ++c) {
      const bool active = rec.shown(c) != 0 || rec.velocity(c) != 0;
      const auto context = static_cast<std::size_t>(channel_update_context(m, c, active, updated_now));
      if (rc.decode(m.channel_updated[c][context]) == 0) continue;
      const int partner = table[c].partner;
      const bool from_partner = partner >= 0 && updated_now[static_cast<std::size_t>(partner)];
      const auto p = static_cast<std::size_t>(from_partner ? partner : 0);
      const std::int32_t q_pred = rec.shown(c);
      // |r| < 2^18 even when corrupt (a partner's residual plus a decoded one).
      const std::int64_t r = (from_partner ? residual[p] : 0) + std::int64_t{decode_signed(rc, m.residual[g][from_partner ? 1 : 0])};
      const std::int64_t q = std::int64_t{q_pred} + r * (std::int64_t{1} << s);
      // The encoder rounds a value in range to the level's units, so it can
      // overshoot the range by less than one unit; more is corruption.
      if (q <= std::int64_t{coded_range(c).min} - (std::int64_t{1} << s) ||
          q >= std::int64_t{coded_range(c).max} + (std::int64_t{1} << s)) {
        rc.fail(DecodeError::value_out_of_range);
      }
      residual[c] = static_cast<std::int32_t>(r);
      u_new[c] = read_motion(rc, m, c, g, s, from_partner, from_partner ? u_new[p] : rec.velocity(c),
                             from_partner ? damping_new[p] : 0, damping_new[c]);
      updated_now[c] = true;
      rec.set(c, clamp_coded(q, c), u_new[c], damping_new[c]);
    }
  }
  for (std::size_t g = 0; g < kChannelGroupCount; ++g) {
    if (!m.group_updated_last[g]) continue;
    const GroupSpan span = group_spans()[g];
    for (std::size_t c = span.first; c < span.first + span.count; ++c) m.updated_last[c] = updated_now[c];
  }
}

}  // namespace

DecodeError read_frame_payload(CodingState& state, FrameType type, std::span<const std::uint8_t> payload,
                               std::uint32_t& tick_delta) {
  RangeDecoder rc(payload);
  if (type == FrameType::key) state.models.reset();
  const std::uint32_t delta_minus_one = decode_unsigned(rc, state.models.tick_delta);
  if (delta_minus_one >= kMaxTickDelta) rc.fail(DecodeError::value_out_of_range);
  tick_delta = delta_minus_one + 1;
  state.reconstruction.advance(tick_delta);
  if (type == FrameType::key) {
    read_key(state, rc);
  } else {
    read_predicted(state, rc);
  }
  if (rc.decode_raw(kCheckBitCount) != kCheckBits) rc.fail(DecodeError::check_failed);
  return rc.error();
}

}  // namespace fw::codec
