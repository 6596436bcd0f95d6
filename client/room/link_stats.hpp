#pragma once
// What the client measures of its link and the room stream: bytes each way,
// frames per avatar, and the latency from the server's simulation tick to
// the client's decode. Printed live, and as one JSON object at the end.
#include <chrono>
#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace fw::client {

class LinkStats {
 public:
  using Clock = std::chrono::steady_clock;

  explicit LinkStats(Clock::time_point start = Clock::now()) : start_(start) {}

  void bytes_down(std::size_t bytes) { bytes_down_ += bytes; }
  void bytes_up(std::size_t bytes) { bytes_up_ += bytes; }
  /// A frame of avatar `avatar` (shown as `name`) decoded.
  void frame(std::uint32_t avatar, const std::string& name);
  /// Milliseconds from the server's tick to this decode; at most
  /// kMaxLatencySamples are kept (a uniform sample once there are more).
  void latency_ms(double milliseconds);
  void reconnected() { ++reconnects_; }
  /// The first welcome: per-avatar times in the summary count from here.
  void joined(Clock::time_point when);
  /// The first welcome, if there was one.
  std::optional<Clock::time_point> joined_at() const {
    return joined_ == Clock::time_point{} ? std::nullopt : std::optional(joined_);
  }
  /// A package of the avatar arrived whole (`full` false: the preview).
  void package(std::uint32_t avatar, bool full, Clock::time_point when);
  void decode_error() { ++decode_errors_; }

  std::uint64_t total_bytes_down() const { return bytes_down_; }
  std::uint64_t total_bytes_up() const { return bytes_up_; }
  /// Avatars at least one frame of which was decoded.
  std::size_t avatars_seen() const;
  std::uint64_t frames_of(std::uint32_t avatar) const;
  /// The p-th percentile (0..100) of the latencies, or -1 if none were measured.
  double latency_percentile_ms(double p) const;

  /// One line for a person: avatars, kbit/s each way (over the last
  /// interval and overall), frames per second, latency.
  std::string live_line(Clock::time_point now);
  /// The summary object: avatars_seen, bytes_down, bytes_up, kbps_down,
  /// kbps_up, seconds (rates and seconds count from the first welcome), frames_per_avatar (name -> count), latency_ms_p50,
  /// latency_ms_p99 (null when not measured), reconnects, decode_errors,
  /// and per avatar (name -> object): frames, fps (from its first frame to
  /// now), fps_recent (over the last kRecentSeconds, what the link carries
  /// now that the start-up is over), first_frame_s, preview_s, full_s (seconds after joining; absent
  /// when it did not happen).
  nlohmann::json summary(Clock::time_point now) const;

  static constexpr std::size_t kMaxLatencySamples = 100000;
  static constexpr double kRecentSeconds = 10.0;

 private:
  struct AvatarFrames {
    std::string name;
    std::uint64_t count = 0;
    std::deque<Clock::time_point> recent;  ///< frame times of the last kRecentSeconds
    Clock::time_point first{}, preview{}, full{};  // {} when not yet
  };
  Clock::time_point start_;
  Clock::time_point joined_{};
  std::uint64_t bytes_down_ = 0, bytes_up_ = 0;
  std::map<std::uint32_t, AvatarFrames> frames_;
  std::vector<double> latencies_ms_;
  std::uint64_t latency_count_ = 0;
  std::minstd_rand sampler_{1};  // fixed seed: the same stream gives the same summary
  std::uint64_t reconnects_ = 0, decode_errors_ = 0;
  // For the live line: counters at the last line.
  Clock::time_point last_line_ = start_;
  std::uint64_t last_down_ = 0, last_up_ = 0, last_frames_ = 0;
};

}  // namespace fw::client
