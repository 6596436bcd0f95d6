#include "link_stats.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace fw::client {
namespace {

double seconds_between(LinkStats::Clock::time_point a, LinkStats::Clock::time_point b) {
  return std::max(1e-6, std::chrono::duration<double>(b - a).count());
}

double round_to(double value, double step) { return std::round(value / step) * step; }

}  // namespace

void LinkStats::frame(std::uint32_t avatar, const std::string& name) {
  AvatarFrames& entry = frames_[avatar];
  entry.name = name;
  const Clock::time_point now = Clock::now();
  if (entry.count++ == 0) entry.first = now;
  entry.recent.push_back(now);
  const auto horizon = now - std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(kRecentSeconds));
  while (entry.recent.front() < horizon) entry.recent.pop_front();
}

void LinkStats::joined(Clock::time_point when) {
  if (joined_ == Clock::time_point{}) joined_ = when;
}

void LinkStats::package(std::uint32_t avatar, bool full, Clock::time_point when) {
  AvatarFrames& entry = frames_[avatar];
  Clock::time_point& slot = full ? entry.full : entry.preview;
  if (slot == Clock::time_point{}) slot = when;
}

void LinkStats::latency_ms(double milliseconds) {
  ++latency_count_;
  if (latencies_ms_.size() < kMaxLatencySamples) {
    latencies_ms_.push_back(milliseconds);
    return;
  }
  // Reservoir sampling keeps a uniform sample without growing.
  const std::uint64_t slot = std::uniform_int_distribution<std::uint64_t>(0, latency_count_ - 1)(sampler_);
  if (slot < kMaxLatencySamples) latencies_ms_[slot] = milliseconds;
}

std::size_t LinkStats::avatars_seen() const {
  std::size_t seen = 0;
  for (const auto& [id, entry] : frames_) seen += entry.count > 0 ? 1 : 0;
  return seen;
}

std::uint64_t LinkStats::frames_of(std::uint32_t avatar) const {
  const auto it = frames_.find(avatar);
  return it == frames_.end() ? 0 : it->second.count;
}

double LinkStats::latency_percentile_ms(double p) const {
  if (latencies_ms_.empty()) return -1;
  std::vector<double> sorted = latencies_ms_;
  const auto rank = static_cast<std::size_t>(std::ceil(p / 100.0 * static_cast<double>(sorted.size()))) ;
  const std::size_t index = std::min(sorted.size() - 1, rank == 0 ? 0 : rank - 1);
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(index), sorted.end());
  return sorted[index];
}

std::string LinkStats::live_line(Clock::time_point now) {
  std::uint64_t frames = 0;
  for (const auto& [id, entry] : frames_) frames += entry.count;
  const double interval = seconds_between(last_line_, now);
  const double down_kbps = static_cast<double>(bytes_down_ - last_down_) * 8.0 / 1000.0 / interval;
  const double up_kbps = static_cast<double>(bytes_up_ - last_up_) * 8.0 / 1000.0 / interval;
  const double fps = static_cast<double>(frames - last_frames_) / interval;
  last_line_ = now;
  last_down_ = bytes_down_;
  last_up_ = bytes_up_;
  last_frames_ = frames;
  char line[200];
  const double p50 = latency_percentile_ms(50);
  std::snprintf(line, sizeof line, "avatars %zu | down %.2f kbit/s | up %.2f kbit/s | %.1f avatar frames/s | latency p50 %s",
                avatars_seen(), down_kbps, up_kbps, fps,
                p50 < 0 ? "-" : (std::to_string(static_cast<int>(std::lround(p50))) + " ms").c_str());
  return line;
}

nlohmann::json LinkStats::summary(Clock::time_point now) const {
  // Rates count from the first welcome: the upload before it is not part of
  // the room's stream.
  const double seconds = seconds_between(joined_ == Clock::time_point{} ? start_ : joined_, now);
  nlohmann::json per_avatar = nlohmann::json::object(), details = nlohmann::json::object();
  const Clock::time_point origin = joined_ == Clock::time_point{} ? start_ : joined_;
  auto after_join = [origin](Clock::time_point t) { return round_to(std::chrono::duration<double>(t - origin).count(), 0.001); };
  std::size_t seen = 0;
  for (const auto& [id, entry] : frames_) {
    if (entry.count == 0) continue;  // a package arrived, but no frame yet
    ++seen;
    // Two avatars may share a name: the later one gets its id appended.
    std::string key = entry.name;
    if (key.empty()) key = "avatar " + std::to_string(id);
    if (per_avatar.contains(key)) key += " #" + std::to_string(id);
    per_avatar[key] = entry.count;
    nlohmann::json detail = {{"frames", entry.count},
                             {"fps", round_to(static_cast<double>(entry.count) / seconds_between(entry.first, now), 0.01)},
                             {"first_frame_s", after_join(entry.first)}};
    // Frames of the last kRecentSeconds (or of the avatar's life, if shorter).
    const auto horizon = now - std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(kRecentSeconds));
    const auto recent = static_cast<double>(
        std::count_if(entry.recent.begin(), entry.recent.end(), [&](Clock::time_point t) { return t >= horizon; }));
    detail["fps_recent"] = round_to(recent / std::min(kRecentSeconds, seconds_between(entry.first, now)), 0.01);
    if (entry.preview != Clock::time_point{}) detail["preview_s"] = after_join(entry.preview);
    if (entry.full != Clock::time_point{}) detail["full_s"] = after_join(entry.full);
    details[key] = detail;
  }
  auto latency = [this](double p) -> nlohmann::json {
    const double value = latency_percentile_ms(p);
    return value < 0 ? nlohmann::json(nullptr) : nlohmann::json(round_to(value, 0.01));
  };
  return {
      {"avatars_seen", seen},
      {"bytes_down", bytes_down_},
      {"bytes_up", bytes_up_},
      {"kbps_down", round_to(static_cast<double>(bytes_down_) * 8.0 / 1000.0 / seconds, 0.001)},
      {"kbps_up", round_to(static_cast<double>(bytes_up_) * 8.0 / 1000.0 / seconds, 0.001)},
      {"seconds", round_to(seconds, 0.001)},
      {"frames_per_avatar", per_avatar},
      {"latency_ms_p50", latency(50)},
      {"latency_ms_p99", latency(99)},
      {"latency_samples", latency_count_},
      {"reconnects", reconnects_},
      {"decode_errors", decode_errors_},
      {"avatars", details},
  };
}

}  // namespace fw::client
