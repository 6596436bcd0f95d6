#include "metrics.hpp"

#include <sstream>

#include "abuse_log.hpp"

namespace fw::server {

void Metrics::observe_tick(double seconds) {
  std::size_t bucket = 0;
  while (bucket < kTickBuckets.size() && seconds > kTickBuckets[bucket]) ++bucket;
  tick_counts[bucket].fetch_add(1, std::memory_order_relaxed);
  tick_sum_us.fetch_add(static_cast<std::uint64_t>(seconds * 1e6), std::memory_order_relaxed);
}

std::string Metrics::render(double physics_share, const AbuseLog& abuse) const {
  std::ostringstream out;
  const auto family = [&](const char* name, const char* type, const char* help, auto value) {
    out << "# HELP " << name << " " << help << "\n# TYPE " << name << " " << type << "\n"
        << name << " " << value << "\n";
  };
  family("facewire_connections", "gauge", "Open room connections (WebSocket and TCP).", connections.load());
  family("facewire_http_connections", "gauge", "Open HTTP connections.", http_connections.load());
  family("facewire_rooms", "gauge", "Rooms.", rooms.load());
  family("facewire_avatars", "gauge", "Avatars in all rooms.", avatars.load());
  family("facewire_bytes_sent_total", "counter", "Bytes written to room connections.", bytes_sent.load());
  family("facewire_bytes_received_total", "counter", "Bytes read from room connections.", bytes_received.load());
  family("facewire_room_frames_sent_total", "counter", "Room frames sent.", room_frames_sent.load());
  family("facewire_avatar_frames_sent_total", "counter", "Avatar frames inside room frames.", avatar_frames_sent.load());
  family("facewire_avatar_frames_shared_total", "counter",
         "Avatar frames sent to a viewer as already encoded for another viewer of the face.",
         avatar_frames_shared.load());
  family("facewire_package_bytes_sent_total", "counter", "Avatar package bytes sent in chunks.", package_bytes_sent.load());
  family("facewire_dropped_ticks_total", "counter", "Subscriber ticks skipped because the link was full.",
         skipped_ticks.load());
  family("facewire_late_ticks_total", "counter", "Room ticks that could not keep their schedule.", late_ticks.load());
  family("facewire_physics_share", "gauge", "Share of faces allowed the physics face; under 1 when the server sheds load.",
         physics_share);
  family("facewire_kinematic_faces", "gauge", "Faces following their targets without the physics face, under load.",
         kinematic_faces.load());
  family("facewire_protocol_errors_total", "counter", "Connections closed for malformed messages.",
         protocol_errors.load());
  family("facewire_rejected_joins_total", "counter", "Hellos refused (token, room full, bad request).",
         rejected_joins.load());
  family("facewire_uploads_total", "counter", "Avatar packages stored from uploads.", uploads.load());
  family("facewire_chat_lines_total", "counter", "Chat lines relayed.", chat_lines.load());
  family("facewire_unsaid_lines_total", "counter",
         "Chat lines shown but not said: the speech queue (--speech-queue) was full.", unsaid_lines.load());
  family("facewire_repreparations_started_total", "counter",
         "Stored avatars of another package format or generic face handed to be prepared again from their photo.",
         repreparations_started.load());
  family("facewire_repreparations_total", "counter", "Stored avatars prepared again from their photo.",
         repreparations.load());
  family("facewire_repreparation_failures_total", "counter",
         "Stored avatars that could not be prepared again from their photo.", repreparation_failures.load());
  family("facewire_outdated_avatars_total", "counter",
         "Stored avatars of another package format or generic face refused: no photo to prepare them again.",
         outdated_avatars.load());
  family("facewire_damaged_avatars_total", "counter", "Stored avatar packages found corrupt and refused.",
         damaged_avatars.load());
  family("facewire_deleted_avatars_total", "counter", "Avatars and their photos deleted by their uploader on this node.",
         deleted_avatars.load());
  family("facewire_expired_avatars_total", "counter",
         "Avatars and their photos deleted after --avatar-retention-days without a use.", expired_avatars.load());

  out << "# HELP facewire_refusals_total Requests, connections and messages refused or cut off, by kind.\n"
      << "# TYPE facewire_refusals_total counter\n";
  for (std::size_t i = 0; i < kAbuseKinds; ++i) {
    const auto kind = static_cast<Abuse>(i);
    out << "facewire_refusals_total{kind=\"" << abuse_name(kind) << "\"} " << abuse.count(kind) << "\n";
  }

  out << "# HELP facewire_tick_duration_seconds Simulation and encoding time of one room tick.\n"
      << "# TYPE facewire_tick_duration_seconds histogram\n";
  std::uint64_t cumulative = 0;
  for (std::size_t i = 0; i < kTickBuckets.size(); ++i) {
    cumulative += tick_counts[i].load();
    out << "facewire_tick_duration_seconds_bucket{le=\"" << kTickBuckets[i] << "\"} " << cumulative << "\n";
  }
  cumulative += tick_counts[kTickBuckets.size()].load();
  out << "facewire_tick_duration_seconds_bucket{le=\"+Inf\"} " << cumulative << "\n"
      << "facewire_tick_duration_seconds_sum " << static_cast<double>(tick_sum_us.load()) / 1e6 << "\n"
      << "facewire_tick_duration_seconds_count " << cumulative << "\n";
  return out.str();
}

}  // namespace fw::server
