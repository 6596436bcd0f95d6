// Encoder: decides, tick by tick, whether the viewer needs a frame and what
// it should say (FORMAT.md, "Encoder" is informative; only the frames it
// writes are normative), within the rate controller's budget.
//
// One tick, step by step (Encoder::encode_tick):
//   observe_steps     the face as coded channels (done once for all the
//                     face's encoders when it comes as a FaceSource)
//   start_tick        the clocks and the rate controller move on
//   observe           each channel's motion, and the frame that would carry all of it
//   remember_source   the source history the next motion estimates use
//   choose_frame      a key frame if one is forced or due, else
//     choose_predicted_frame   which channels the viewer needs (select_updates);
//                     over budget, fit_over_budget keeps the most urgent;
//                     each frame tried is written into the coding state
//                     (write_trial) and a refused one taken back (undo_trial)
//   commit_frame      the frame goes out: the coding state, clocks and stats follow
#include <algorithm>
#include <cassert>
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>

#include "channel_table.hpp"
#include "coding_state.hpp"
#include "model_journal.hpp"
#include "prefetch.hpp"
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
// The corrective weights only spend what the budget has to spare: a frame
// carries them while the rate control's pressure is under
// kCorrectivePressure (the 0.75 under which it would go finer: the rest of
// the face leaves bits over) and the bucket stays under
// kCorrectiveBucketShare of its capacity (a second of budget); they alone
// make a frame only then. Their bits fill the bucket but do not count in
// the spending that sets the level (RateController::on_frame_sent), so they
// never make the level coarser for the rest. So a tight link spends its
// bits on gaze and action units and holds the correctives.
constexpr double kCorrectivePressure = 0.75;
constexpr double kCorrectiveBucketShare = 1.0 / 3.0;

// The correctives are the table's last channels (channel_table.cpp; held by
// ChannelTable.CorrectivesCoverMinusOneToOneAndComeLast): asked for every
// channel every tick, a comparison.
constexpr std::size_t kFirstCorrective = kChannelCount - kCorrectiveCount;
bool is_corrective(std::size_t c) { return c >= kFirstCorrective; }

using Steps = std::array<double, kChannelCount>;
using Updates = std::array<bool, kChannelCount>;
using Priorities = std::array<double, kChannelCount>;  ///< each channel's error over its tolerance

constexpr std::size_t kEyeLeftYaw = kAuChannelCount + 6;
constexpr std::size_t kEyeRightYaw = kAuChannelCount + 8;

// This tick's face as coded channels (grid steps, unrounded), the motion each
// channel shows, and the frame that would carry all of it.
struct TickSource {
  Steps x{};
  Steps velocity{};
  FrameDecision wanted;
};

// Why a predicted frame is needed, if at all.
enum class FrameNeed {
  none,         ///< every channel within its tolerance, no heartbeat or refresh due
  change,       ///< the viewer would see a difference, or a heartbeat is due
  refresh,      ///< nothing the viewer would see, but the face moved since the last frame
  correctives,  ///< only corrective weights beyond their tolerance: sent on spare budget
};

}  // namespace

// What each channel may be off by at each quality level, in grid steps,
// for one set of options. Every tick asks for every channel's, up to three
// times; encoders with the same visible errors (a server's, all of them)
// share one table, which stays in the cache, instead of each holding its own.
struct EncoderTolerances {
  std::array<float, kChannelCount> visible_error{};
  float max_gaze_error_rad = 0;
  std::array<std::array<double, kChannelCount>, kMaxQualityLevel + 1> steps{};

  explicit EncoderTolerances(const EncoderOptions& o) : visible_error(o.visible_error), max_gaze_error_rad(o.max_gaze_error_rad) {
    for (std::size_t level = 0; level <= kMaxQualityLevel; ++level)
      for (std::size_t c = 0; c < kChannelCount; ++c) {
        double error = visible_error[c] * kLevelFactor[level];
        if (channel_table()[c].group == ChannelGroup::eyes) error = std::min<double>(error, max_gaze_error_rad);
        steps[level][c] = error / channel_table()[c].step;
      }
  }
  bool made_for(const EncoderOptions& o) const {
    return visible_error == o.visible_error && max_gaze_error_rad == o.max_gaze_error_rad;
  }
};

// The table for `options`: one already in use by an encoder, or a new one.
std::shared_ptr<const EncoderTolerances> shared_tolerances(const EncoderOptions& options) {
  static std::mutex mutex;
  static std::vector<std::weak_ptr<const EncoderTolerances>> tables;
  const std::lock_guard lock(mutex);
  std::erase_if(tables, [](const auto& weak) { return weak.expired(); });
  for (const auto& weak : tables)
    if (auto table = weak.lock(); table && table->made_for(options)) return table;
  auto table = std::make_shared<const EncoderTolerances>(options);
  tables.push_back(table);
  return table;
}

namespace {

// The face as coded channels, grid steps, unrounded (all a held tick needs).
void observe_steps(const FaceParams& params, Steps& x) {
  const auto& table = channel_table();
  for (std::size_t c = 0; c < kChannelCount; ++c) {
    x[c] = to_steps(channel_value(params, c), c);
    const int base = table[c].base;
    if (base >= 0) x[c] += x[static_cast<std::size_t>(base)];  // bases come first in the table
  }
}

}  // namespace

struct Encoder::State {
  // A frame being tried: its bytes. The trial writes into the encoder's coding
  // state itself, and a trial the budget refuses is taken back (TrialUndo): a
  // copy of the state before every trial (the adaptive models take kilobytes)
  // cost the server more than the frames did.
  struct FrameTrial {
    std::vector<std::uint8_t> bytes;
    FrameType type = FrameType::predicted;
    /// The share of the frame's bits that carries corrective weights (their
    /// share of the channels it updates; none in a key frame, which every
    /// channel needs).
    double corrective_share = 0;
  };

  // What a trial frame changed in the coding state, kept to take it back: the
  // reconstruction (a few hundred bytes), the level and the models' history
  // whole, the adaptive models through the journal of those the frame touched
  // (a few dozen), except in a key frame, which resets them all (rare: a
  // stream's first frame, a resync). A trial lives within one encode() call,
  // so one per thread serves every encoder (trial_scratch): a server holds
  // an encoder per avatar per viewer, and what each one holds is memory the
  // cache has to bring in.
  struct TrialUndo {
    bool pending = false;
    bool key = false;
    Reconstruction reconstruction;
    int level = 0;
    std::array<bool, kChannelCount> updated_last{};
    std::array<bool, kChannelGroupCount> group_updated_last{};
    ModelJournal journal;
    std::optional<FrameModels> models;  ///< key frames only
  };

  struct Scratch {
    TrialUndo undo;
    FrameTrial trial;  ///< its buffer kept from tick to tick
  };
  static Scratch& trial_scratch() {
    thread_local Scratch scratch;
    return scratch;
  }

  explicit State(const EncoderOptions& o)
      : options(o), rate(o.target_bps, o.stream.tick_rate_hz, o.min_level, o.max_level),
        coding(o.stream.max_extrapolation_ticks), tolerances(shared_tolerances(o)) {}

  EncoderOptions options;
  RateController rate;
  CodingState coding;  ///< what the decoder holds after the last frame sent
  std::shared_ptr<const EncoderTolerances> tolerances;
  bool started = false;
  bool key_requested = true;
  std::uint64_t offered = 0;  ///< faces offered so far
  std::uint32_t ticks_since_frame = 0;
  std::uint32_t ticks_since_key = 0;
  std::uint8_t sequence = 0;
  int history = 0;          ///< ticks of source history held (0 .. 2)
  EncoderStats stats;
  /// The history this tick's motion estimate reads: previous and
  /// before_previous, or a FaceSource's own.
  const Steps* past = nullptr;
  const Steps* past2 = nullptr;
  // (Above: what every tick reads, kept together.)
  Steps sent_source{};      ///< the source when the last frame went out
  Steps previous{};         ///< the source one tick ago, grid steps (faces offered as FaceParams)
  Steps before_previous{};  ///< two ticks ago

  // ---- The tick's source -------------------------------------------------

  // The clocks move on by one tick, and the budget drains by one tick's worth.
  void start_tick() {
    ++offered;
    stats.tick = static_cast<std::uint32_t>(offered - 1);
    stats.sent = false;
    ticks_since_frame = std::min(ticks_since_frame + 1, kMaxTickDelta);
    ticks_since_key = std::min(ticks_since_key + 1, kMaxTickDelta);
    rate.on_tick();
  }

  TickSource observe(const Steps& steps, int level) const {
    TickSource source;
    source.x = steps;
    source.wanted.tick_delta = ticks_since_frame;
    source.wanted.level = level;
    for (std::size_t c = 0; c < kChannelCount; ++c) {
      const double x = source.x[c];
      // A corrective is sent without velocity: it may be held for long on a
      // tight link, and a held one must stand still, not drift on.
      const Motion motion = is_corrective(c) ? Motion{} : estimate_motion(c, x, tolerance(c, level));
      source.velocity[c] = motion.velocity;
      source.wanted.target[c] = round_nearest(x);
      source.wanted.velocity[c] = round_nearest(motion.velocity * kSubSteps);
      source.wanted.damping[c] = motion.damping;
    }
    return source;
  }

  // Every offered tick enters the history, sent or not (a FaceSource keeps
  // its own: only the count is the encoder's).
  void remember_source(const Steps& x, bool own) {
    if (own) {
      before_previous = previous;
      previous = x;
    }
    history = std::min(history + 1, 2);
  }

  // The error channel `c` may show at `level`, in grid steps.
  double tolerance(std::size_t c, int level) const { return tolerances->steps[static_cast<std::size_t>(level)][c]; }

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
    const double d1 = x - (*past)[c];
    const double d2 = (*past)[c] - (*past2)[c];
    if (d1 == 0.0 || d2 == 0.0 || (d1 > 0) != (d2 > 0)) return {};
    // A drift too slow to matter before the extrapolation stops is not worth its bits.
    if (std::abs(d1) * horizon < 0.5 * tolerance) return {};
    const double ratio = d1 / d2;
    if (ratio < kDampingRatio) {
      const int damping = nearest_damping(ratio);
      return {d1 * kept(damping), damping};
    }
    if (ratio > kBurstRatio) return {};
    return {d1 + kAcceleration * (d1 - d2), 0};
  }
  // The velocity decays by (1 - numerator/64) per tick: the class nearest the observed ratio.
  static int nearest_damping(double ratio) {
    int best = 1;
    for (int d = 2; d < kDampingClasses; ++d)
      if (std::abs(kept(d) - ratio) < std::abs(kept(best) - ratio)) best = d;
    return best;
  }

  // ---- Which channels a predicted frame updates ----------------------------

  // Which channels a predicted frame at this tick should update, given the
  // source `x` and its `velocity` (grid steps); `priority` gets each
  // channel's error over its tolerance.
  FrameNeed select_updates(const Steps& x, const Steps& velocity, int level, Updates& update,
                           Priorities& priority) const {
    Steps error{};
    bool corrective_off = false;
    const bool channel_off = mark_channels_off(x, velocity, level, error, update, priority, corrective_off);
    const bool eye_off = mark_eyes_off(error, level, update, priority);
    FrameNeed need = FrameNeed::change;
    if (!heartbeat_due() && !channel_off && !eye_off && corrective_off) {
      need = FrameNeed::correctives;
    } else if (!heartbeat_due() && !channel_off && !eye_off) {
      // A refresh: every channel is within its tolerance of the prediction,
      // but the face moved since the last frame (some channel by half a
      // grid step or more). The frame carries the channel the prediction
      // misses most for its tolerance, and everything it misses by a share
      // of its own, with fresh velocities.
      if (!refresh_due() || !moved_since_sent(x)) return FrameNeed::none;
      need = FrameNeed::refresh;
      update[static_cast<std::size_t>(std::max_element(priority.begin(), priority.end()) - priority.begin())] = true;
    }
    mark_partners(error, level, update);
    return need;
  }

  // Each channel's error against what the decoder shows now (the last
  // frame's state extrapolated by the ticks since, read without a copy), its
  // priority, and whether a frame should update it: past a share of its
  // tolerance now, or past all of it in a few ticks. Returns whether any
  // channel but the correctives is beyond its tolerance (`corrective_off`:
  // whether a corrective is).
  bool mark_channels_off(const Steps& x, const Steps& velocity, int level, Steps& error, Updates& update,
                         Priorities& priority, bool& corrective_off) const {
    const Reconstruction& view = coding.reconstruction;
    bool beyond = false;
    for (std::size_t c = 0; c < kChannelCount; ++c) {
      const double limit = tolerance(c, level);
      error[c] = x[c] - view.shown_after(c, ticks_since_frame);
      const double error_ahead =
          x[c] + velocity[c] * kLookaheadTicks - view.shown_after(c, ticks_since_frame + kLookaheadTicks);
      (is_corrective(c) ? corrective_off : beyond) |= std::abs(error[c]) > limit;
      priority[c] = std::abs(error[c]) / limit;
      update[c] = std::abs(error[c]) > kUpdateShare * limit || std::abs(error_ahead) > limit;
    }
    return beyond;
  }

  // An eye's two channels are its gaze direction in the world: the viewer
  // sees the angle between where it should look and where it looks. Returns
  // whether either eye is beyond its tolerance.
  bool mark_eyes_off(const Steps& error, int level, Updates& update, Priorities& priority) const {
    bool beyond = false;
    for (const std::size_t yaw : {kEyeLeftYaw, kEyeRightYaw}) {
      const std::size_t pitch = yaw + 1;
      const double off = std::hypot(error[yaw], error[pitch]) / tolerance(yaw, level);
      // Eye contact first: an eye beyond its tolerance outranks everything else.
      priority[yaw] = priority[pitch] = off > 1.0 ? off + kGazePriority : off;
      if (off <= 1.0) continue;
      beyond = true;
      if (!update[yaw] && !update[pitch]) update[yaw] = update[pitch] = true;
    }
    return beyond;
  }

  // A frame goes out at least this often: the tick delta must stay codable,
  // and a loss-tolerant stream's viewer must notice a lost frame.
  bool heartbeat_due() const {
    return ticks_since_frame >= kMaxTickDelta ||
           (options.stream.loss_tolerant && ticks_since_frame >= static_cast<std::uint32_t>(options.heartbeat_ticks));
  }

  bool refresh_due() const {
    return options.refresh_ticks > 0 && ticks_since_frame >= static_cast<std::uint32_t>(options.refresh_ticks);
  }

  // Whether some channel moved by half a grid step or more since the last
  // frame (a face that holds still has nothing to refresh).
  bool moved_since_sent(const Steps& x) const {
    for (std::size_t c = 0; c < kChannelCount; ++c)
      if (std::abs(x[c] - sent_source[c]) >= 0.5) return true;
    return false;
  }

  // Left and right go together once either is off by a share of its
  // tolerance: the right side's residual is coded against the left's.
  void mark_partners(const Steps& error, int level, Updates& update) const {
    for (std::size_t c = 0; c < kChannelCount; ++c) {
      const int p = channel_table()[c].partner;
      if (p < 0) continue;
      const auto partner = static_cast<std::size_t>(p);
      const double limit = kPartnerShare * tolerance(c, level);
      if (update[partner] && std::abs(error[c]) > limit) update[c] = true;
      if (update[c] && std::abs(error[partner]) > limit) update[partner] = true;
    }
  }

  // A frame is about to be written: its adaptive models (kilobytes, last
  // touched a frame ago, so long out of the cache on a server holding
  // thousands of encoders) are asked for all at once. The range coder reads
  // them one after another in a chain that waits for each; fetched
  // together, the misses overlap instead of adding up.
  void prefetch_models() const {
    const auto* bytes = reinterpret_cast<const char*>(&coding.models);
    for (std::size_t offset = 0; offset < sizeof(FrameModels); offset += 64) __builtin_prefetch(bytes + offset);
  }

  // ---- Which frame goes out ------------------------------------------------

  // Whether a frame goes out this tick; `trial` then holds it.
  bool choose_frame(const TickSource& source, int level, FrameTrial& trial) {
    const bool key_forced = !started || key_requested;
    if (key_forced || key_due_by_clock()) {
      FrameDecision key = source.wanted;
      key.type = FrameType::key;
      if (try_frame(key, source.wanted, key_forced, trial)) return true;
      // A key frame that is only due by the clock waits for room in the
      // budget; meanwhile the stream goes on with predicted frames (from
      // the state before the key frame tried).
      if (key_forced) return false;
      undo_trial();
    }
    return choose_predicted_frame(source, level, trial);
  }

  // Loss-tolerant streams send key frames at the rate controller's interval.
  bool key_due_by_clock() const {
    return options.stream.loss_tolerant &&
           ticks_since_key >= static_cast<std::uint32_t>(rate.key_interval_ticks(options.max_key_interval_ticks));
  }

  bool choose_predicted_frame(const TickSource& source, int level, FrameTrial& trial) {
    FrameDecision decision = source.wanted;
    decision.type = FrameType::predicted;
    Priorities priority{};
    const FrameNeed need = select_updates(source.x, source.velocity, level, decision.update, priority);
    if (need == FrameNeed::none) return false;
    // Correctives go only on spare budget; with none spare (the bucket
    // already holds a share) no trial frame is written for them at all.
    const bool spare = rate.pressure() < kCorrectivePressure &&
                       rate.bucket_bits() + overhead_bits() <= kCorrectiveBucketShare * rate.capacity_bits();
    if (need == FrameNeed::correctives && !spare) return false;
    if (!spare) drop_correctives(decision);
    // A refresh whose only news were correctives has nothing left to say.
    const auto& update = decision.update;
    if (need == FrameNeed::refresh && std::none_of(update.begin(), update.end(), [](bool u) { return u; })) return false;
    prefetch_models();
    const bool fits = try_frame(decision, source.wanted, false, trial);
    if (need == FrameNeed::refresh) return fits && refresh_affordable(trial);
    if (need == FrameNeed::correctives) return fits && within_share(trial, kCorrectiveBucketShare);
    if (fits && (!updates_correctives(decision) || within_share(trial, kCorrectiveBucketShare))) return true;
    if (updates_correctives(decision)) {
      // The correctives would take more than the spare budget: the frame goes without them.
      drop_correctives(decision);
      if (try_frame(decision, source.wanted, false, trial)) return true;
    }
    return fit_over_budget(decision, priority, source.wanted, trial);
  }

  static bool updates_correctives(const FrameDecision& decision) {
    for (std::size_t c = 0; c < kChannelCount; ++c)
      if (decision.update[c] && is_corrective(c)) return true;
    return false;
  }
  static void drop_correctives(FrameDecision& decision) {
    for (std::size_t c = 0; c < kChannelCount; ++c) decision.update[c] = decision.update[c] && !is_corrective(c);
  }

  // Whether the bucket stays under `share` of its capacity with `trial` in it.
  bool within_share(const FrameTrial& trial, double share) const {
    return rate.bucket_bits() + 8.0 * static_cast<double>(trial.bytes.size()) + overhead_bits() <=
           share * rate.capacity_bits();
  }

  // A refresh only spends what the budget has to spare (refresh_bucket_share).
  bool refresh_affordable(const FrameTrial& trial) const { return within_share(trial, options.refresh_bucket_share); }

  // Over budget: keep the channels furthest beyond their tolerance, as many
  // as fit; channels far off (an eye beyond its tolerance, anything beyond
  // twice its own) may dip into the reserve rather than wait. Only when not
  // even one fits is the tick skipped (the decoder keeps showing its
  // prediction).
  bool fit_over_budget(const FrameDecision& decision, const Priorities& priority, const FrameDecision& wanted,
                       FrameTrial& trial) {
    const std::vector<std::size_t> order = updates_by_priority(decision.update, priority);
    auto try_first = [&](std::size_t keep, bool urgent) {
      return try_frame(first_by_priority(decision, order, keep, priority), wanted, urgent, trial);
    };
    for (std::size_t keep = order.size() / 2; keep >= 1; keep /= 2)
      if (try_first(keep, false)) return true;
    std::size_t urgent = 0;
    while (urgent < order.size() && priority[order[urgent]] > kUrgentPriority) ++urgent;
    for (std::size_t keep = urgent; keep >= 1; keep /= 2)
      if (try_first(keep, true)) return true;
    // The tick delta must stay codable: after 65536 silent ticks a frame goes out whatever the budget.
    if (ticks_since_frame < kMaxTickDelta) return false;
    try_first(0, true);
    return true;
  }

  // The channels to update, most urgent first (ties keep channel order).
  static std::vector<std::size_t> updates_by_priority(const Updates& update, const Priorities& priority) {
    std::vector<std::size_t> order;
    order.reserve(kChannelCount);
    for (std::size_t c = 0; c < kChannelCount; ++c)
      if (update[c]) order.push_back(c);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return priority[a] > priority[b]; });
    return order;
  }

  // `decision` cut down to the first `keep` channels of `order`, plus what
  // must go with them. The eyes go together: half a gaze update would leave
  // the other eye, or the other axis, where it was. A head far off goes with
  // them: an eye is coded as gaze in the world and shown as gaze minus the
  // head the decoder holds, so under a stale head it looks the wrong way.
  static FrameDecision first_by_priority(const FrameDecision& decision, const std::vector<std::size_t>& order,
                                         std::size_t keep, const Priorities& priority) {
    FrameDecision reduced = decision;
    reduced.update = {};
    bool eyes = false;
    for (std::size_t i = 0; i < keep; ++i) {
      reduced.update[order[i]] = true;
      eyes = eyes || channel_table()[order[i]].group == ChannelGroup::eyes;
    }
    if (eyes)
      for (const std::size_t c : order) {
        const ChannelGroup group = channel_table()[c].group;
        if (group == ChannelGroup::eyes || (group == ChannelGroup::head_rotation && priority[c] > kUrgentPriority))
          reduced.update[c] = true;
      }
    return reduced;
  }

  // ---- Trying and sending a frame --------------------------------------------

  // Writes `decision` into `trial`; whether the budget takes it. Models that
  // learned small changes can make a sudden whole-face change cost more than
  // a frame may hold; a key frame (fresh models) stays well under the limit.
  bool try_frame(const FrameDecision& decision, const FrameDecision& wanted, bool urgent, FrameTrial& trial) {
    write_trial(decision, trial);
    if (trial.bytes.size() > kMaxFrameBytes) {
      FrameDecision key = wanted;
      key.type = FrameType::key;
      write_trial(key, trial);
    }
    return rate.allows(8.0 * static_cast<double>(trial.bytes.size()) + overhead_bits(), urgent);
  }

  // Writes `decision` into the coding state (after taking back any trial
  // before it), keeping what it changes in `undo`.
  void write_trial(const FrameDecision& decision, FrameTrial& trial) {
    undo_trial();
    TrialUndo& undo = trial_scratch().undo;  // this thread's: an encoder may be called from any
    const bool key = decision.type == FrameType::key;
    undo.pending = true;
    undo.key = key;
    undo.reconstruction = coding.reconstruction;
    undo.level = coding.level;
    undo.updated_last = coding.models.updated_last;
    undo.group_updated_last = coding.models.group_updated_last;
    if (key) undo.models = coding.models;
    trial.bytes.clear();
    write_frame(coding, options.stream, sequence, decision, trial.bytes, key ? nullptr : &undo.journal);
    trial.type = decision.type;
    trial.corrective_share = 0;
    if (decision.type == FrameType::key) return;
    std::size_t updated = 0, correctives = 0;
    for (std::size_t c = 0; c < kChannelCount; ++c) {
      updated += decision.update[c] ? 1 : 0;
      correctives += decision.update[c] && is_corrective(c) ? 1 : 0;
    }
    if (updated > 0) trial.corrective_share = static_cast<double>(correctives) / static_cast<double>(updated);
  }

  // The coding state goes back to before the trial frame, if one was written.
  void undo_trial() {
    TrialUndo& undo = trial_scratch().undo;
    if (!undo.pending) return;
    undo.pending = false;
    coding.reconstruction = undo.reconstruction;
    coding.level = undo.level;
    if (undo.key) {
      coding.models = *undo.models;
    } else {
      undo.journal.undo();
      coding.models.updated_last = undo.updated_last;
      coding.models.group_updated_last = undo.group_updated_last;
    }
  }

  // What the container adds to every frame, charged to the budget.
  double overhead_bits() const { return 8.0 * options.container_bytes_per_frame; }

  // The frame goes out: the decoder will hold the coding state it left, and
  // the clocks, budget and stats count it.
  void commit_frame(FrameTrial& trial, const Steps& x) {
    const double bits = 8.0 * static_cast<double>(trial.bytes.size()) + overhead_bits();
    const bool key = trial.type == FrameType::key;
    TrialUndo& undo = trial_scratch().undo;
    undo.pending = false;
    undo.journal.clear();
    sent_source = x;
    rate.on_frame_sent(bits, key, bits * trial.corrective_share);
    ticks_since_frame = 0;
    if (key) {
      ticks_since_key = 0;
      key_requested = false;
      started = true;
    }
    ++sequence;
    stats.sent = true;
    stats.last_type = trial.type;
    stats.last_bytes = trial.bytes.size();
    ++stats.frames_sent;
    stats.bytes_sent += trial.bytes.size();
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
  Steps x;
  observe_steps(params, x);
  encode_tick(x, nullptr, none, false);
}

bool Encoder::encode(const FaceParams& params, std::vector<std::uint8_t>& frame) {
  Steps x;
  observe_steps(params, x);
  return encode_tick(x, nullptr, frame, true);
}

void Encoder::hold(const FaceSource& source) {
  std::vector<std::uint8_t> none;
  encode_tick(source.x_, &source, none, false);
}

bool Encoder::encode(const FaceSource& source, std::vector<std::uint8_t>& frame) {
  return encode_tick(source.x_, &source, frame, true);
}

void FaceSource::offer(const FaceParams& params) {
  before_previous_ = previous_;
  previous_ = x_;
  observe_steps(params, x_);
  ++ticks_;
}

bool Encoder::encode_tick(const std::array<double, kChannelCount>& x, const FaceSource* source,
                          std::vector<std::uint8_t>& frame, bool may_send) {
  State& s = *state_;
  frame.clear();
  s.start_tick();
  if (!may_send) {
    // A held tick only moves the clocks and the source history on.
    s.remember_source(x, source == nullptr);
    return false;
  }
  prefetch_whole(s);  // a frame reads lines all over the state (prefetch.hpp)
  s.past = source != nullptr ? &source->previous_ : &s.previous;
  s.past2 = source != nullptr ? &source->before_previous_ : &s.before_previous;
  const int level = s.rate.level();
  const TickSource tick_source = s.observe(x, level);
  s.remember_source(x, source == nullptr);
  State::FrameTrial& trial = State::trial_scratch().trial;
  if (!s.choose_frame(tick_source, level, trial)) {
    s.undo_trial();
    return false;
  }
  s.commit_frame(trial, x);
  frame.assign(trial.bytes.begin(), trial.bytes.end());
  return true;
}

}  // namespace fw::codec
