#pragma once
// Physics level of detail under load. The physics face is the costliest part
// of a room tick; when the worker pool cannot keep the rooms' schedule, the
// whole simulation would otherwise run in slow motion for everybody. The
// governor watches how late room ticks start and sets the share of faces
// that may run physics: it backs off quickly while ticks are late (x0.7 per
// window) and comes back slowly while they are on time (+0.05 per window
// with at most 1 % of its ticks late),
// as congestion control does. Faces beyond the share follow their targets
// kinematically (RoomSimulation::set_physics_share).
//
// Shedding physics only helps while physics is what fills the pool: the
// rooms' other work (encoders for every subscriber, fan-out) and other
// processes on the cores make ticks late too, and shedding every face then
// would cost the whole physics face for nothing. So the governor also
// weighs what the rooms' ticks cost (observe_work: their own work, and
// their faces' tissue step on the pool, FaceStepper) and backs off only in
// a window where the tissue took at least kPhysicsPartToShed of it, and no
// further than where the tissue would take that part; while ticks are late
// and the tissue takes less, the share holds.
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
  /// Seconds of work of the rooms' ticks besides their faces' tissue
  /// (behaviour, measure, encoders), and seconds of the tissue's steps.
  /// Without any, every late window backs off.
  void observe_room_work(double seconds);
  void observe_physics_work(double seconds);

  /// Share of faces that may run physics now, 0 .. 1.
  double share() const { return share_.load(std::memory_order_relaxed); }

  static constexpr double kLateFraction = 0.05;  ///< over this share of late ticks in a window: back off
  static constexpr double kBackOff = 0.7;  ///< the deepest cut of one window
  static constexpr double kRecovery = 0.05;
  /// A window with at most this share of its ticks late gives physics
  /// back. Not none: a hundred rooms tick 3000 times a second, and on cores
  /// shared with other work a few of them always start late (a time slice
  /// elsewhere), whatever the share; a window had to be spotless to
  /// recover, so the share only ever fell (100 rooms of 10 drifted from
  /// 0.26 to 0.20 in 40 s and stayed there). One tick in a hundred half a
  /// period late stays well inside a p99 tick-to-decode of 50 ms.
  static constexpr double kOnTimeFraction = 0.01;
  /// A late window backs off only if the tissue took this share of the
  /// rooms' work or more: a third, so that shedding it all could win back
  /// a third of the work, a tick of 33 ms late by 11. It cuts down to where
  /// the tissue would take a third if its cost followed the share, no
  /// further: at 100 rooms of 10 on 2 cores, the tissue some 36 % of the
  /// workers' time at a share of 0.33, a cut by 30 % landed at 0.23 where
  /// the cores carried 0.31 (30 Hz). (A lower part lowers that floor: 28 %
  /// cut to 0.23 there as well.) Batched solves cost more per face on fewer
  /// faces, so a later late window may cut again (server/README.md).
  static constexpr double kPhysicsPartToShed = 1.0 / 3.0;

  /// What a late window multiplies the share by, given the rooms' own work
  /// and their tissue's over it (seconds): 1 while the tissue takes less
  /// than kPhysicsPartToShed, else the cut that leaves it that part, by
  /// kBackOff at most.
  static double back_off(double room_seconds, double physics_seconds);

 private:
  std::atomic<double> share_{1.0};
  std::mutex mutex_;  // guards the window below
  bool enabled_;
  Clock::duration window_;
  Clock::time_point window_start_{};
  std::uint64_t ticks_ = 0;
  std::uint64_t late_ = 0;
  double room_seconds_ = 0, physics_seconds_ = 0;  ///< in the window
};

}  // namespace fw::server
