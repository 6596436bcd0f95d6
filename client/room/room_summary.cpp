#include "room_summary.hpp"

namespace fw::client {

nlohmann::json room_summary(const RoomState& state, std::chrono::steady_clock::time_point now) {
  nlohmann::json summary = state.stats.summary(now);
  summary["room"] = state.room;
  summary["server"] = state.server;
  summary["you"] = state.you;
  summary["avatars_in_room"] = state.avatars.size();
  std::size_t packages = 0;
  for (const auto& [id, avatar] : state.avatars) packages += avatar.package ? 1 : 0;
  summary["avatars_with_package"] = packages;
  nlohmann::json events = nlohmann::json::array();
  const auto joined = state.stats.joined_at();
  for (const RoomEventRecord& event : state.events) {
    nlohmann::json entry = {{"kind", event.kind}, {"name", event.name}, {"text", event.text}};
    if (event.kind == "speaking") {
      entry["language"] = event.language;
      entry["duration_ms"] = event.duration_ms;
      entry["tick"] = event.tick;
    }
    // Seconds after the first welcome (negative: before it).
    if (joined) entry["at_s"] = std::chrono::duration<double>(event.at - *joined).count();
    events.push_back(std::move(entry));
  }
  summary["events"] = events;
  if (!state.mutes.empty()) {
    // Whom the person muted, and how many of their lines were not shown.
    std::size_t muted_here = 0;
    for (const auto& [id, avatar] : state.avatars) muted_here += state.muted(id) ? 1 : 0;
    summary["muted"] = {{"names", state.mutes.names()},
                        {"avatars_in_room", muted_here},
                        {"lines_hidden", state.mutes.hidden_lines()}};
  }
  if (state.server_link)
    summary["server_link"] = {{"target_bps", state.server_link->target_bps},
                              {"drain_bps", state.server_link->drain_bps},
                              {"queued_bytes", state.server_link->queued_bytes},
                              {"skipped_ticks", state.server_link->skipped_ticks}};
  return summary;
}

}  // namespace fw::client
