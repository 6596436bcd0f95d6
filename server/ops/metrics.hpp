#pragma once
// The server's counters and the tick-duration histogram, rendered in the
// Prometheus text format at /metrics. Lock-free: every thread adds.
#include <array>
#include <atomic>
#include <cstdint>
#include <string>

namespace fw::server {

struct Metrics {
  std::atomic<std::int64_t> connections{0};        ///< room connections (WebSocket and TCP)
  std::atomic<std::int64_t> http_connections{0};
  std::atomic<std::int64_t> rooms{0};
  std::atomic<std::int64_t> avatars{0};
  std::atomic<std::uint64_t> bytes_sent{0};
  std::atomic<std::uint64_t> bytes_received{0};
  std::atomic<std::uint64_t> room_frames_sent{0};
  std::atomic<std::uint64_t> avatar_frames_sent{0};
  std::atomic<std::uint64_t> avatar_frames_shared{0};  ///< of those, encoded once for several viewers (shared_encoder.hpp)
  std::atomic<std::uint64_t> package_bytes_sent{0};
  std::atomic<std::uint64_t> skipped_ticks{0};      ///< subscriber ticks dropped: the link was full
  std::atomic<std::uint64_t> late_ticks{0};         ///< room ticks that started after their time
  std::atomic<std::int64_t> kinematic_faces{0};     ///< faces following their targets without physics, under load
  std::atomic<std::uint64_t> protocol_errors{0};
  std::atomic<std::uint64_t> rejected_joins{0};
  std::atomic<std::uint64_t> uploads{0};
  std::atomic<std::uint64_t> chat_lines{0};
  std::atomic<std::uint64_t> unsaid_lines{0};  ///< lines shown but not said: the speech queue was full
  // Stored avatars whose package is of another format or generic face
  // version (avatar_store.hpp): handed to be prepared again from their
  // photo, prepared again, failed; refused for want of a photo.
  std::atomic<std::uint64_t> repreparations_started{0};
  std::atomic<std::uint64_t> repreparations{0};
  std::atomic<std::uint64_t> repreparation_failures{0};
  std::atomic<std::uint64_t> outdated_avatars{0};
  std::atomic<std::uint64_t> damaged_avatars{0};  ///< stored packages found corrupt
  std::atomic<std::uint64_t> deleted_avatars{0};  ///< deleted by their uploader (here, not on other nodes)
  std::atomic<std::uint64_t> expired_avatars{0};  ///< swept after --avatar-retention-days unused

  /// Upper bounds of the tick-duration buckets in seconds (simulation and
  /// encoding of one room tick).
  static constexpr std::array<double, 10> kTickBuckets = {0.0005, 0.001, 0.002, 0.005, 0.01,
                                                          0.02,   0.033, 0.05,  0.1,   0.25};
  std::array<std::atomic<std::uint64_t>, kTickBuckets.size() + 1> tick_counts{};
  std::atomic<std::uint64_t> tick_sum_us{0};

  void observe_tick(double seconds);
  /// The whole exposition, one family after another. `physics_share` is the
  /// PhysicsGovernor's, which owns it.
  /// `abuse` adds its refusals by kind.
  std::string render(double physics_share, const class AbuseLog& abuse) const;
};

}  // namespace fw::server
