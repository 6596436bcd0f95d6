// Encoder: decides, tick by tick, whether the viewer needs a frame and what
// it should say (FORMAT.md, "Encoder" is informative; only the frames it
// writes are normative), within the rate controller's budget.
#include <algorithm>
#include <cassert>
#include <cmath>
#include <optional>

#include "channel_table.hpp"
#include "coding_state.hpp"
#include "frame_writer.hpp"
#include "fw/codec/codec.hpp"
#include "quantiser.hpp"
#include "rate_controller.hpp"

namespace fw::codec {
namespace {

// A channel is updated in a frame that goes out anyway once its error passes
// this share of its tolerance: one more channel costs little in a frame that
// is paid for, and it postpones the next frame.
constexpr double kUpdateShare = 0.5;
// ... and when it would pass its tolerance within this many ticks at the
// source's current velocity.
constexpr std::uint32_t kLookaheadTicks = 2;
// A ramp's velocity is sent as its last step plus this share of its last
// change: a ramp that speeds up is sent at the speed of the ticks to come.
constexpr double kAcceleration = 1.0;
// Two steps whose ratio is under this are a glide that slows down: damped.
constexpr double kDampingRatio = 0.9;
// A step this much larger than the one before is the start of a saccade or
// a blink, whose end is near: it gets no velocity.
constexpr double kBurstRatio = 2.5;
// A right-side channel follows its partner's update from this share on: its
// residual is coded against the partner's and costs almost nothing when the
// face is symmetric.
constexpr double kPartnerShare = 0.3;
// Added to the priority of an eye beyond its tolerance (priorities are
// errors over tolerances, so 2 and more is urgent).
constexpr double kGazePriority = 100.0;
constexpr double kUrgentPriority = 2.0;

using Steps = std::array<double, kChannelCount>;

constexpr std::size_t kEyeLeftYaw = kAuChannelCount + 6;
constexpr std::size_t kEyeRightYaw = kAuChannelCount + 8;

}  // namespace

struct Encoder::State {
  explicit State(const EncoderOptions& o)
      : options(o), rate(o.target_bps, o.stream.tick_rate_hz, o.min_level, o.max_level),
        coding(o.stream.max_extrapolation_ticks) {}

  EncoderOptions options;
  RateController rate;
  CodingState coding;  ///< what the decoder holds after the last frame sent
  bool started = false;
  bool key_requested = true;
  std::uint64_t offered = 0;  ///< faces offered so far
  std::uint32_t ticks_since_frame = 0;
  std::uint32_t ticks_since_key = 0;
  std::uint8_t sequence = 0;
  Steps previous{};         ///< the source one tick ago, grid steps
  Steps before_previous{};  ///< two ticks ago
  Steps sent_source{};      ///< the source when the last frame went out
  int history = 0;          ///< ticks of source history held (0 .. 2)
  EncoderStats stats;

  // The error channel `c` may show at `level`, in grid steps.
  double tolerance(std::size_t c, int level) const {
    double error = options.visible_error[c] * kLevelFactor[static_cast<std::size_t>(level)];
    if (channel_table()[c].group == ChannelGroup::eyes) error = std::min<double>(error, options.max_gaze_error_rad);
    return error / channel_table()[c].step;
  }

  // Which channels a predicted frame at this tick should update, given the
  // source `x` and its `velocity` (grid steps). Returns false when no frame
  // is needed: every channel is within its tolerance of what the decoder
  // shows, and no heartbeat is due. `priority` gets each channel's error
  // over its tolerance.
  bool select_updates(const Steps& x, const Steps& velocity, int level, std::array<bool, kChannelCount>& update,
                      std::array<double, kChannelCount>& priority, bool& refresh) const {
    refresh = false;
    // What the decoder shows now: the last frame's state extrapolated by
    // the ticks since (the same as advancing a copy, without the copy).
    const Reconstruction& view = coding.reconstruction;
    bool needed = ticks_since_frame >= kMaxTickDelta ||
                  (options.stream.loss_tolerant && ticks_since_frame >= static_cast<std::uint32_t>(options.heartbeat_ticks));
    Steps error{};
    for (std::size_t c = 0; c < kChannelCount; ++c) {
      const double limit = tolerance(c, level);
      error[c] = x[c] - view.shown_after(c, ticks_since_frame);
      const double error_ahead =
          x[c] + velocity[c] * kLookaheadTicks - view.shown_after(c, ticks_since_frame + kLookaheadTicks);
      needed = needed || std::abs(error[c]) > limit;
      priority[c] = std::abs(error[c]) / limit;
      update[c] = std::abs(error[c]) > kUpdateShare * limit || std::abs(error_ahead) > limit;
    }
    // An eye's two channels are its gaze direction in the world: the viewer
    // sees the angle between where it should look and where it looks.
    for (const std::size_t yaw : {kEyeLeftYaw, kEyeRightYaw}) {
      const std::size_t pitch = yaw + 1;
      const double off = std::hypot(error[yaw], error[pitch]) / tolerance(yaw, level);
      // Eye contact first: an eye beyond its tolerance outranks everything else.
      priority[yaw] = priority[pitch] = off > 1.0 ? off + kGazePriority : off;
      if (off <= 1.0) continue;
      needed = true;
      if (!update[yaw] && !update[pitch]) update[yaw] = update[pitch] = true;
    }
    if (!needed && options.refresh_ticks > 0 && ticks_since_frame >= static_cast<std::uint32_t>(options.refresh_ticks)) {
      // A refresh: every channel is within its tolerance of the prediction,
      // but the face moved since the last frame (some channel by half a
      // grid step or more). The frame carries the channel the prediction
      // misses most for its tolerance, and everything it misses by a share
      // of its own, with fresh velocities.
      bool moved = false;
      for (std::size_t c = 0; c < kChannelCount && !moved; ++c) moved = std::abs(x[c] - sent_source[c]) >= 0.5;
      if (!moved) return false;  // the face holds still: nothing to refresh
      needed = refresh = true;
      update[static_cast<std::size_t>(std::max_element(priority.begin(), priority.end()) - priority.begin())] = true;
    }
    if (!needed) return false;
    for (std::size_t c = 0; c < kChannelCount; ++c) {
      const int p = channel_table()[c].partner;
      if (p < 0) continue;
      const auto partner = static_cast<std::size_t>(p);
      const double limit = kPartnerShare * tolerance(c, level);
      if (update[partner] && std::abs(error[c]) > limit) update[c] = true;
      if (update[c] && std::abs(error[partner]) > limit) update[partner] = true;
    }
    return true;
  }

  // The motion to send for channel `c` (source now at `x` grid steps): a
  // velocity in grid steps per tick and a damping class. Two steps in the
  // same direction are a ramp: a slowing one (each step under 0.9 of the
  // last) glides with the damping whose decay matches, any other keeps a
  // linear velocity. A step after stillness, or a reversal, sends no
  // velocity (a saccade would overshoot it).
  static double kept(int damping_class) { return 1.0 - static_cast<double>(kDampingNumerator[damping_class]) / 64.0; }
  struct Motion {
    double velocity = 0;
    int damping = 0;
  };
  Motion estimate_motion(std::size_t c, double x, double tolerance) const {
    const std::uint8_t horizon = options.stream.max_extrapolation_ticks;
    if (history < 2 || horizon == 0) return {};
    const double d1 = x - previous[c];
    const double d2 = previous[c] - before_previous[c];
    if (d1 == 0.0 || d2 == 0.0 || (d1 > 0) != (d2 > 0)) return {};
    // A drift too slow to matter before the extrapolation stops is not worth its bits.
    if (std::abs(d1) * horizon < 0.5 * tolerance) return {};
    const double ratio = d1 / d2;
    if (ratio < kDampingRatio) {
      // The velocity decays by (1 - numerator/64) per tick: take the class nearest the observed ratio.
      int best = 1;
      for (int d = 2; d < kDampingClasses; ++d)
        if (std::abs(kept(d) - ratio) < std::abs(kept(best) - ratio)) best = d;
      return {d1 * kept(best), best};
    }
    if (ratio > kBurstRatio) return {};
    return {d1 + kAcceleration * (d1 - d2), 0};
  }
};

Encoder::Encoder(const EncoderOptions& options) : state_(std::make_unique<State>(options)) {
  assert(options.max_key_interval_ticks >= 1 && options.heartbeat_ticks >= 1 && options.refresh_ticks >= 0);
}
Encoder::~Encoder() = default;
Encoder::Encoder(Encoder&&) noexcept = default;
Encoder& Encoder::operator=(Encoder&&) noexcept = default;

void Encoder::set_target_bps(double bits_per_second) { state_->rate.set_target_bps(bits_per_second); }
void Encoder::force_key_frame() { state_->key_requested = true; }
const EncoderOptions& Encoder::options() const { return state_->options; }

QuantisedParams Encoder::reconstruction() const {
  // The decoder extrapolates from the last frame sent up to this tick.
  return fields_from_coded(state_->coding.reconstruction.shown_all(state_->ticks_since_frame));
}

EncoderStats Encoder::stats() const {
  EncoderStats s = state_->stats;
  s.level = state_->rate.level();
  s.bucket_bits = state_->rate.bucket_bits();
  s.bucket_capacity_bits = state_->rate.capacity_bits();
  s.key_interval_ticks = state_->options.stream.loss_tolerant
                             ? state_->rate.key_interval_ticks(state_->options.max_key_interval_ticks)
                             : 0;
  return s;
}

void Encoder::hold(const FaceParams& params) {
  std::vector<std::uint8_t> none;
  encode_tick(params, none, false);
}

bool Encoder::encode(const FaceParams& params, std::vector<std::uint8_t>& frame) {
  return encode_tick(params, frame, true);
}

bool Encoder::encode_tick(const FaceParams& params, std::vector<std::uint8_t>& frame, bool may_send) {
  State& s = *state_;
  frame.clear();
  ++s.offered;
  s.stats.tick = static_cast<std::uint32_t>(s.offered - 1);
  s.stats.sent = false;
  s.ticks_since_frame = std::min(s.ticks_since_frame + 1, kMaxTickDelta);
  s.ticks_since_key = std::min(s.ticks_since_key + 1, kMaxTickDelta);
  s.rate.on_tick();
  const int level = s.rate.level();

  // This tick's face as coded channels (grid steps, unrounded), and the
  // motion each channel shows.
  Steps x{};
  FrameDecision wanted;
  wanted.tick_delta = s.ticks_since_frame;
  wanted.level = level;
  Steps velocity{};
  for (std::size_t c = 0; c < kChannelCount; ++c) {
    x[c] = to_steps(channel_value(params, c), c);
    const int base = channel_table()[c].base;
    if (base >= 0) x[c] += x[static_cast<std::size_t>(base)];  // bases come first in the table
    const State::Motion motion = s.estimate_motion(c, x[c], s.tolerance(c, level));
    velocity[c] = motion.velocity;
    wanted.target[c] = round_nearest(x[c]);
    wanted.velocity[c] = round_nearest(motion.velocity * kSubSteps);
    wanted.damping[c] = motion.damping;
  }
  s.before_previous = s.previous;
  s.previous = x;
  s.history = std::min(s.history + 1, 2);
  if (!may_send) return false;

  const double overhead_bits = 8.0 * s.options.container_bytes_per_frame;
  // The state after the frame being tried: copied only when a frame is
  // tried (most ticks send none, and the adaptive models take kilobytes).
  std::optional<CodingState> next;
  std::vector<std::uint8_t> bytes;
  // Writes `decision` into `next` and `bytes`; whether the budget takes it.
  FrameType type = FrameType::predicted;
  auto try_frame = [&](const FrameDecision& decision, bool urgent) {
    next = s.coding;
    bytes.clear();
    write_frame(*next, s.options.stream, s.sequence, decision, bytes);
    type = decision.type;
    if (bytes.size() > kMaxFrameBytes) {
      // Models that learned small changes can make a sudden whole-face
      // change cost more than a frame may hold; a key frame (fresh models)
      // stays well under the limit.
      FrameDecision key = wanted;
      key.type = FrameType::key;
      next = s.coding;
      bytes.clear();
      write_frame(*next, s.options.stream, s.sequence, key, bytes);
      type = FrameType::key;
    }
    return s.rate.allows(8.0 * static_cast<double>(bytes.size()) + overhead_bits, urgent);
  };

  bool fits = false;
  const bool key_forced = !s.started || s.key_requested;
  const bool key_due =
      key_forced || (s.options.stream.loss_tolerant &&
                     s.ticks_since_key >= static_cast<std::uint32_t>(
                                              s.rate.key_interval_ticks(s.options.max_key_interval_ticks)));
  if (key_due) {
    FrameDecision key = wanted;
    key.type = FrameType::key;
    fits = try_frame(key, key_forced);
    // A key frame that is only due by the clock waits for room in the
    // budget; meanwhile the stream goes on with predicted frames.
    if (!fits && key_forced) return false;
  }
  if (!fits) {
    FrameDecision decision = wanted;
    decision.type = FrameType::predicted;
    std::array<double, kChannelCount> priority{};  // error over tolerance
    bool refresh = false;
    if (!s.select_updates(x, velocity, level, decision.update, priority, refresh)) return false;
    fits = try_frame(decision, false);
    // A refresh only spends what the budget has to spare (refresh_bucket_share).
    if (refresh && (!fits || s.rate.bucket_bits() + 8.0 * static_cast<double>(bytes.size()) + overhead_bits >
                                 s.options.refresh_bucket_share * s.rate.capacity_bits()))
      return false;
    if (!fits) {
      // Over budget: keep the channels furthest beyond their tolerance, as
      // many as fit; channels far off (an eye beyond its tolerance, anything
      // beyond twice its own) may dip into the reserve rather than wait.
      // Only when not even one fits is the tick skipped (the decoder keeps
      // showing its prediction).
      std::vector<std::size_t> order;
      for (std::size_t c = 0; c < kChannelCount; ++c)
        if (decision.update[c]) order.push_back(c);
      std::stable_sort(order.begin(), order.end(),
                       [&](std::size_t a, std::size_t b) { return priority[a] > priority[b]; });
      auto try_first = [&](std::size_t keep, bool urgent) {
        FrameDecision reduced = decision;
        reduced.update = {};
        bool eyes = false;
        for (std::size_t i = 0; i < keep; ++i) {
          reduced.update[order[i]] = true;
          eyes = eyes || channel_table()[order[i]].group == ChannelGroup::eyes;
        }
        // The eyes go together: half a gaze update would leave the other eye,
        // or the other axis, where it was. A head far off goes with them: an
        // eye is coded as gaze in the world and shown as gaze minus the head
        // the decoder holds, so under a stale head it looks the wrong way.
        if (eyes)
          for (const std::size_t c : order) {
            const ChannelGroup group = channel_table()[c].group;
            if (group == ChannelGroup::eyes || (group == ChannelGroup::head_rotation && priority[c] > kUrgentPriority))
              reduced.update[c] = true;
          }
        return try_frame(reduced, urgent);
      };
      for (std::size_t keep = order.size() / 2; keep >= 1 && !fits; keep /= 2) fits = try_first(keep, false);
      std::size_t urgent = 0;
      while (urgent < order.size() && priority[order[urgent]] > kUrgentPriority) ++urgent;
      for (std::size_t keep = urgent; keep >= 1 && !fits; keep /= 2) fits = try_first(keep, true);
      // The tick delta must stay codable: after 65536 silent ticks a frame goes out whatever the budget.
      if (!fits && s.ticks_since_frame >= kMaxTickDelta) {
        try_first(0, true);
        fits = true;
      }
    }
    if (!fits) return false;
  }

  const double bits = 8.0 * static_cast<double>(bytes.size()) + overhead_bits;
  s.coding = std::move(*next);
  s.sent_source = x;
  s.rate.on_frame_sent(bits, type == FrameType::key);
  s.ticks_since_frame = 0;
  if (type == FrameType::key) {
    s.ticks_since_key = 0;
    s.key_requested = false;
    s.started = true;
  }
  ++s.sequence;
  s.stats.sent = true;
  s.stats.last_type = type;
  s.stats.last_bytes = bytes.size();
  ++s.stats.frames_sent;
  s.stats.bytes_sent += bytes.size();
  frame = std::move(bytes);
  return true;
}

}  // namespace fw::codec
