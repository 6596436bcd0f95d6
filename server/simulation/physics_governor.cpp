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
  const double work = room_seconds_ + physics_seconds_;
  const bool physics_fills = work <= 0 || physics_seconds_ >= kPhysicsPartToShed * work;
  double share = share_.load(std::memory_order_relaxed);
  if (late_fraction > kLateFraction) {
    if (physics_fills) share *= kBackOff;
  } else if (late_ == 0) {
    share = std::min(1.0, share + kRecovery);
  }
  share_.store(share < 0.01 ? 0.0 : share, std::memory_order_relaxed);
  window_start_ = started;
  ticks_ = late_ = 0;
  room_seconds_ = physics_seconds_ = 0;
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
