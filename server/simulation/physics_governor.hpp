#pragma once
// Physics level of detail under load. The physics face is the costliest part
// of a room tick; when the worker pool cannot keep the rooms' schedule, the
// whole simulation would otherwise run in slow motion for everybody. The
// governor watches how late room ticks start and sets the share of faces
// that may run physics: it backs off quickly while ticks are late (x0.7 per
// window) and comes back slowly while they are on time (+0.05 per window),
// as congestion control does. Faces beyond the share follow their targets
// kinematically (RoomSimulation::set_physics_share).
//
// Thread-safe: every room's strand reports, anyone reads.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>

namespace fw::server {

class PhysicsGovernor {
 public:
  using Clock = std::chrono::steady_clock;

  /// @param[in] enabled  false: the share stays 1 (every face runs physics)
  /// @param[in] window   how long each decision looks back
  explicit PhysicsGovernor(bool enabled = true, Clock::duration window = std::chrono::seconds(1));

  void set_enabled(bool enabled);

  /// A room tick due at `due` started at `started`; `period` is the tick
  /// period. A tick more than half a period late counts as late.
  void observe_tick(Clock::time_point due, Clock::time_point started, Clock::duration period);

  /// Share of faces that may run physics now, 0 .. 1.
  double share() const { return share_.load(std::memory_order_relaxed); }

  static constexpr double kLateFraction = 0.05;  ///< over this share of late ticks in a window: back off
  static constexpr double kBackOff = 0.7;
  static constexpr double kRecovery = 0.05;

 private:
  std::atomic<double> share_{1.0};
  std::mutex mutex_;  // guards the window below
  bool enabled_;
  Clock::duration window_;
  Clock::time_point window_start_{};
  std::uint64_t ticks_ = 0;
  std::uint64_t late_ = 0;
};

}  // namespace fw::server
