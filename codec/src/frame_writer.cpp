#include "frame_writer.hpp"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>

#include "channel_table.hpp"
#include "integer_coding.hpp"
#include "quantiser.hpp"
#include "range_encoder.hpp"

namespace fw::codec {
namespace {

std::int32_t velocity_unit(int shift) { return kVelocityUnitSubSteps << shift; }

// Velocity units to add to `predicted` to come nearest `wanted`, keeping the
// result within the channel's velocity limit (`predicted` is within it).
std::int32_t velocity_delta(std::int32_t wanted, std::int32_t predicted, std::int32_t unit, std::size_t c) {
  const std::int32_t limit = max_velocity(c);
  wanted = std::clamp(wanted, -limit, limit);
  auto dv = round_nearest(static_cast<double>(wanted - predicted) / unit);
  while (std::abs(std::int64_t{predicted} + std::int64_t{dv} * unit) > limit) dv += dv > 0 ? -1 : 1;
  return dv;
}

// The velocity and damping of channel `c` after its update: the delta from
// `predicted` in the level's units, then the damping class if it moves.
// Returns the new velocity; `damping` gets the class coded.
std::int32_t write_motion(RangeEncoder& rc, FrameModels& m, const FrameDecision& d, std::size_t c, std::size_t g,
                          int shift, bool from_partner, std::int32_t predicted, int partner_damping, int& damping) {
  const std::int32_t unit = velocity_unit(shift);
  const std::int32_t dv = velocity_delta(d.velocity[c], predicted, unit, c);
  encode_signed(rc, m.velocity[g][from_partner ? 1 : 0], dv);
  const std::int32_t velocity = predicted + dv * unit;
  damping = velocity == 0 ? 0 : d.damping[c];
  if (velocity != 0)
    encode_damping(rc, m.damping[g][from_partner ? static_cast<std::size_t>(1 + partner_damping) : 0], damping);
  return velocity;
}

void write_key(CodingState& state, RangeEncoder& rc, const FrameDecision& d) {
  FrameModels& m = state.models;  // reset by write_frame before the tick delta
  state.level = d.level;
  rc.encode_raw(static_cast<std::uint32_t>(d.level), kLevelBits);
  const auto& table = channel_table();
  ChannelValues q_new{};
  std::array<std::int32_t, kChannelCount> u_new{};
  std::array<int, kChannelCount> damping_new{};
  for (std::size_t c = 0; c < kChannelCount; ++c) {
    const ChannelInfo& info = table[c];
    const std::size_t g = group_index(info.group);
    const int s = group_shift(d.level, g);
    const std::int32_t k = round_to_units(d.target[c], s);
    const std::int32_t q = clamp_coded(std::int64_t{k} * (std::int64_t{1} << s), c);
    bool coded = false;
    if (info.partner >= 0) {
      const bool same = q == q_new[static_cast<std::size_t>(info.partner)];
      rc.encode(m.key_same_as_partner[g], same ? 1 : 0);
      coded = same;
    }
    if (!coded) {
      rc.encode(m.key_nonzero[g], k != 0 ? 1 : 0);
      if (k != 0) {
        const std::int32_t k_min = round_to_units(coded_range(c).min, s);
        const std::int32_t k_max = round_to_units(coded_range(c).max, s);
        rc.encode_raw(static_cast<std::uint32_t>(k - k_min), std::bit_width(static_cast<std::uint32_t>(k_max - k_min)));
      }
    }
    const bool from_partner = info.partner >= 0;
    const auto p = static_cast<std::size_t>(from_partner ? info.partner : 0);
    q_new[c] = q;
    u_new[c] = write_motion(rc, m, d, c, g, s, from_partner, from_partner ? u_new[p] : 0,
                            from_partner ? damping_new[p] : 0, damping_new[c]);
    state.reconstruction.set(c, q, u_new[c], damping_new[c]);
  }
}

void write_predicted(CodingState& state, RangeEncoder& rc, const FrameDecision& d) {
  FrameModels& m = state.models;
  Reconstruction& rec = state.reconstruction;
  const bool level_changed = d.level != state.level;
  rc.encode(m.level_changed, level_changed ? 1 : 0);
  if (level_changed) rc.encode_raw(static_cast<std::uint32_t>(d.level), kLevelBits);
  state.level = d.level;
  const auto& table = channel_table();
  std::array<bool, kChannelCount> updated_now{};
  std::array<std::int32_t, kChannelCount> residual{};
  std::array<std::int32_t, kChannelCount> u_new{};
  std::array<int, kChannelCount> damping_new{};
  for (std::size_t g = 0; g < kChannelGroupCount; ++g) {
    const GroupSpan span = group_spans()[g];
    const bool any = std::any_of(d.update.begin() + static_cast<std::ptrdiff_t>(span.first),
                                 d.update.begin() + static_cast<std::ptrdiff_t>(span.first + span.count),
                                 [](bool u) { return u; });
    rc.encode(m.group_updated[g][m.group_updated_last[g] ? 1 : 0], any ? 1 : 0);
    m.group_updated_last[g] = any;
    if (!any) continue;
    const int s = group_shift(d.level, g);
    for (std::size_t c = span.first; c < span.first + span.count; ++c) {
      const bool active = rec.shown(c) != 0 || rec.velocity(c) != 0;
      rc.encode(m.channel_updated[c][static_cast<std::size_t>(channel_update_context(m, c, active, updated_now))],
                           d.update[c] ? 1 : 0);
      if (!d.update[c]) continue;
      const int partner = table[c].partner;
      const bool from_partner = partner >= 0 && updated_now[static_cast<std::size_t>(partner)];
      const auto p = static_cast<std::size_t>(from_partner ? partner : 0);
      const std::int32_t q_pred = rec.shown(c);
      const std::int32_t r = round_to_units(d.target[c] - q_pred, s);
      encode_signed(rc, m.residual[g][from_partner ? 1 : 0], r - (from_partner ? residual[p] : 0));
      residual[c] = r;
      u_new[c] = write_motion(rc, m, d, c, g, s, from_partner, from_partner ? u_new[p] : rec.velocity(c),
                              from_partner ? damping_new[p] : 0, damping_new[c]);
      updated_now[c] = true;
      rec.set(c, clamp_coded(std::int64_t{q_pred} + std::int64_t{r} * (std::int64_t{1} << s), c), u_new[c],
              damping_new[c]);
    }
  }
  // A group not updated in this frame keeps the history of its last update:
  // a channel that moved with its group last time likely moves with it again.
  for (std::size_t g = 0; g < kChannelGroupCount; ++g) {
    if (!m.group_updated_last[g]) continue;
    const GroupSpan span = group_spans()[g];
    for (std::size_t c = span.first; c < span.first + span.count; ++c) m.updated_last[c] = updated_now[c];
  }
}

}  // namespace

void write_frame(CodingState& state, const StreamOptions& options, std::uint8_t sequence,
                 const FrameDecision& decision, std::vector<std::uint8_t>& out, ModelJournal* journal) {
  assert(decision.type == FrameType::key || decision.type == FrameType::predicted);
  assert(decision.tick_delta >= 1 && decision.tick_delta <= kMaxTickDelta);
  assert(decision.level >= 0 && decision.level <= kMaxQualityLevel);
  out.push_back(first_byte(decision.type));
  if (options.loss_tolerant) out.push_back(sequence);
  state.reconstruction.advance(decision.tick_delta);
  RangeEncoder rc(out, journal);
  if (decision.type == FrameType::key) state.models.reset();  // before the tick delta: a key frame stands alone
  encode_unsigned(rc, state.models.tick_delta, decision.tick_delta - 1);
  if (decision.type == FrameType::key) {
    write_key(state, rc, decision);
  } else {
    write_predicted(state, rc, decision);
  }
  rc.encode_raw(kCheckBits, kCheckBitCount);
  rc.finish_into();
}

}  // namespace fw::codec
