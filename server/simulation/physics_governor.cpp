#include "physics_governor.hpp"

#include <algorithm>

namespace fw::server {

PhysicsGovernor::PhysicsGovernor(bool enabled, Clock::duration window) : enabled_(enabled), window_(window) {}

void PhysicsGovernor::set_enabled(bool enabled) {
  const std::lock_guard lock(mutex_);
  enabled_ = enabled;
  if (!enabled) share_.store(1.0, std::memory_order_relaxed);
}

void PhysicsGovernor::observe_tick(Clock::time_point due, Clock::time_point started, Clock::duration period) {
  const std::lock_guard lock(mutex_);
  if (!enabled_) return;
  if (window_start_ == Clock::time_point{}) window_start_ = started;
  ++ticks_;
  if (started - due > period / 2) ++late_;
  if (started - window_start_ < window_) return;
  // One decision per window, on the counts of every room.
  const double late_fraction = static_cast<double>(late_) / static_cast<double>(ticks_);
  double share = share_.load(std::memory_order_relaxed);
  if (late_fraction > kLateFraction) {
    share *= back_off(room_seconds_, physics_seconds_);
  } else if (late_fraction <= kOnTimeFraction) {
    share = std::min(1.0, share + kRecovery);
  }
  share_.store(share < 0.01 ? 0.0 : share, std::memory_order_relaxed);
  window_start_ = started;
  ticks_ = late_ = 0;
  room_seconds_ = physics_seconds_ = 0;
}

double PhysicsGovernor::back_off(double room_seconds, double physics_seconds) {
  const double work = room_seconds + physics_seconds;
  if (work <= 0) return kBackOff;  // nobody says what the work is: shed as if it were the tissue
  const double part = physics_seconds / work;
  if (part < kPhysicsPartToShed) return 1.0;
  // The cut r that leaves the tissue the part k = kPhysicsPartToShed of the
  // work if its cost follows the share (r p / (1 - p + r p) = k): cutting
  // further, the tissue would no longer be what fills the pool, and the
  // share would land below what the pool carries.
  const double to_threshold = kPhysicsPartToShed * (1 - part) / (part * (1 - kPhysicsPartToShed));
  return std::max(kBackOff, to_threshold);
}

void PhysicsGovernor::observe_room_work(double seconds) {
  const std::lock_guard lock(mutex_);
  room_seconds_ += seconds;
}

void PhysicsGovernor::observe_physics_work(double seconds) {
  const std::lock_guard lock(mutex_);
  physics_seconds_ += seconds;
}

}  // namespace fw::server
