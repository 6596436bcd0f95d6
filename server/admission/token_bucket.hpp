#pragma once
// A token bucket: `burst` tokens at most, refilled at `rate` a second. What
// a limit allows on average (rate) and at once (burst).
#include <algorithm>
#include <chrono>

namespace fw::server {

struct BucketRate {
  double per_second = 1;
  double burst = 1;
};

class TokenBucket {
 public:
  using Clock = std::chrono::steady_clock;

  TokenBucket() = default;
  TokenBucket(BucketRate rate, Clock::time_point now) : rate_(rate), tokens_(rate.burst), last_(now) {}

  /// Takes `cost` tokens if the bucket holds them.
  bool take(Clock::time_point now, double cost = 1) {
    refill(now);
    if (tokens_ < cost) return false;
    tokens_ -= cost;
    return true;
  }
  /// Takes `cost` tokens spent elsewhere (another node of a cluster), as
  /// many as there are above `keep` (what was taken here stays taken).
  void spend(Clock::time_point now, double cost, double keep = 0) {
    refill(now);
    tokens_ = std::max(std::min(tokens_, keep), tokens_ - cost);
  }
  /// Seconds until `cost` tokens are there (0: now).
  double seconds_until(Clock::time_point now, double cost = 1) {
    refill(now);
    if (tokens_ >= cost || rate_.per_second <= 0) return tokens_ >= cost ? 0 : 1e9;
    return (cost - tokens_) / rate_.per_second;
  }
  /// Whether the bucket is full: a bucket nobody used lately, safe to forget.
  bool full(Clock::time_point now) {
    refill(now);
    return tokens_ >= rate_.burst;
  }

 private:
  void refill(Clock::time_point now) {
    const double elapsed = std::chrono::duration<double>(now - last_).count();
    if (elapsed > 0) {
      tokens_ = std::min(rate_.burst, tokens_ + elapsed * rate_.per_second);
      last_ = now;
    }
  }

  BucketRate rate_;
  double tokens_ = 1;
  Clock::time_point last_{};
};

}  // namespace fw::server
