#include "rate_controller.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace fw::codec {
namespace {

constexpr double kBucketSeconds = 3.0;     // burst allowance: a busy second may take twice the budget
constexpr double kAverageTicks = 90.0;     // memory of the spending average, 3 s at 30 Hz
constexpr double kCoarserPressure = 0.95;  // spending near the budget, or the bucket 3/4 full
constexpr double kFinerPressure = 0.75;
constexpr double kFullBucket = 0.75;
constexpr double kUrgentReserve = 1.5;   // urgent frames may fill the bucket to 1.5 times its size
constexpr int kTicksBeforeCoarser = 15;
constexpr int kTicksBeforeFiner = 60;
constexpr int kStartLevel = 3;             // just visible (visible_error.cpp)
constexpr double kDefaultKeyBits = 250;    // until the first key frame is measured
constexpr double kKeyShareInverse = 8.0;   // periodic key frames take an eighth of the budget ...
constexpr int kMinKeySeconds = 2;          // ... and come at most every 2 s

}  // namespace

RateController::RateController(double target_bps, int tick_rate_hz, int min_level, int max_level)
    : tick_rate_hz_(tick_rate_hz), min_level_(min_level), max_level_(max_level),
      level_(std::clamp(kStartLevel, min_level, max_level)) {
  assert(tick_rate_hz > 0 && min_level >= 0 && min_level <= max_level && max_level <= 7);
  set_target_bps(target_bps);
}

void RateController::set_target_bps(double target_bps) {
  assert(target_bps > 0);
  bits_per_tick_ = target_bps / tick_rate_hz_;
  capacity_bits_ = target_bps * kBucketSeconds;
}

void RateController::on_tick() {
  average_bits_per_tick_ += (spent_this_tick_ - average_bits_per_tick_) / kAverageTicks;
  spent_this_tick_ = 0;
  bucket_bits_ = std::max(0.0, bucket_bits_ - bits_per_tick_);
  ++ticks_since_level_change_;
  const double now = pressure();
  if (level_ < max_level_ && ticks_since_level_change_ >= kTicksBeforeCoarser && now > kCoarserPressure) {
    ++level_;
    ticks_since_level_change_ = 0;
  } else if (level_ > min_level_ && ticks_since_level_change_ >= kTicksBeforeFiner && now < kFinerPressure) {
    --level_;
    ticks_since_level_change_ = 0;
  }
}

double RateController::pressure() const {
  // Above 1: spending more than the budget, or eating into the burst reserve.
  return std::max(average_bits_per_tick_ / bits_per_tick_,
                  kCoarserPressure * bucket_bits_ / (kFullBucket * capacity_bits_));
}

bool RateController::allows(double bits, bool urgent) const {
  return bucket_bits_ <= 0.0 || bucket_bits_ + bits <= capacity_bits_ * (urgent ? kUrgentReserve : 1.0);
}

void RateController::on_frame_sent(double bits, bool key, double optional_bits) {
  bucket_bits_ += bits;
  spent_this_tick_ += bits - optional_bits;
  if (key) last_key_bits_ = bits;
}

int RateController::key_interval_ticks(int max_ticks) const {
  const double key_bits = last_key_bits_ > 0 ? last_key_bits_ : kDefaultKeyBits;
  const double ticks = std::ceil(kKeyShareInverse * key_bits / bits_per_tick_);
  return static_cast<int>(std::clamp(ticks, static_cast<double>(std::min(kMinKeySeconds * tick_rate_hz_, max_ticks)),
                                     static_cast<double>(max_ticks)));
}

}  // namespace fw::codec
