#include "address_limits.hpp"

#include <algorithm>

namespace fw::server {

AddressLimits::AddressLimits(const AbuseLimits& limits) : limits_(limits) {}

bool AddressLimits::open_connection(const std::string& key) {
  std::lock_guard lock(mutex_);
  Entry& entry = entries_[key];
  if (entry.connections + remote_connections(key, Clock::now()) >= limits_.connections_per_address) return false;
  ++entry.connections;
  return true;
}

void AddressLimits::close_connection(const std::string& key) {
  std::lock_guard lock(mutex_);
  const auto it = entries_.find(key);
  if (it == entries_.end() || it->second.connections == 0) return;
  --it->second.connections;
  forget_if_idle(it, Clock::now());
}

std::size_t AddressLimits::connections(const std::string& key) const {
  std::lock_guard lock(mutex_);
  const auto it = entries_.find(key);
  return it == entries_.end() ? 0 : it->second.connections;
}

BucketRate rate_of(const AbuseLimits& limits, AddressRate rate) {
  switch (rate) {
    case AddressRate::join: return limits.joins;
    case AddressRate::chat: return limits.chat;
    case AddressRate::upload: return limits.uploads;
    case AddressRate::room_creation: return limits.room_creations;
    case AddressRate::script: return limits.scripts;
    case AddressRate::look_save: return limits.look_saves;
    case AddressRate::avatar_look_save: return limits.avatar_look_saves;
  }
  return {};
}

BucketRate AddressLimits::rate_of(AddressRate rate) const { return server::rate_of(limits_, rate); }

std::optional<double> AddressLimits::take(AddressRate rate, const std::string& key, Clock::time_point now) {
  std::lock_guard lock(mutex_);
  if (++takes_since_sweep_ >= 4096 && takes_since_sweep_ >= entries_.size()) sweep(now);
  auto it = entries_.try_emplace(key).first;
  auto& bucket = it->second.buckets[static_cast<std::size_t>(rate)];
  if (!bucket) bucket.emplace(rate_of(rate), now);
  if (bucket->take(now)) {
    // An avatar's own rate is kept on each node: the other nodes take
    // addresses only in their limits news (cluster_limits.hpp).
    if (sharing_ && rate != AddressRate::avatar_look_save) spent_[{key, rate}] += 1;
    return std::nullopt;
  }
  return bucket->seconds_until(now);
}

std::vector<AddressLimits::Spent> AddressLimits::take_spending() {
  std::lock_guard lock(mutex_);
  std::vector<Spent> spent;
  for (const auto& [what, tokens] : spent_) spent.push_back({what.first, what.second, tokens});
  spent_.clear();
  return spent;
}

void AddressLimits::charge(AddressRate rate, const std::string& key, double tokens, Clock::time_point now,
                           std::chrono::duration<double> longest_wait) {
  std::lock_guard lock(mutex_);
  auto it = entries_.try_emplace(key).first;
  auto& bucket = it->second.buckets[static_cast<std::size_t>(rate)];
  const BucketRate bucket_rate = rate_of(rate);
  if (!bucket) bucket.emplace(bucket_rate, now);
  // The next token is due within `longest_wait`: what refills meanwhile is kept.
  const double keep = std::max(0.0, 1.0 - bucket_rate.per_second * longest_wait.count());
  bucket->spend(now, std::min(tokens, bucket_rate.burst), keep);
}

std::map<std::string, std::size_t> AddressLimits::connection_counts() const {
  std::lock_guard lock(mutex_);
  std::map<std::string, std::size_t> counts;
  for (const auto& [key, entry] : entries_)
    if (entry.connections != 0) counts[key] = entry.connections;
  return counts;
}

void AddressLimits::set_remote_connections(const std::string& node, std::map<std::string, std::size_t> counts,
                                           Clock::time_point now, Clock::time_point expires) {
  std::lock_guard lock(mutex_);
  for (auto it = remote_.begin(); it != remote_.end();) it = it->second.expires <= now ? remote_.erase(it) : std::next(it);
  if (counts.empty()) return (void)remote_.erase(node);
  if (!remote_.count(node) && remote_.size() >= kMaxRemoteNodes) return;
  for (auto& [key, count] : counts) count = std::min(count, limits_.connections_per_address);
  remote_[node] = {std::move(counts), expires};
}

std::size_t AddressLimits::remote_connections(const std::string& key, Clock::time_point now) const {
  std::size_t total = 0;
  for (const auto& [node, remote] : remote_)
    if (const auto it = remote.counts.find(key); it != remote.counts.end() && remote.expires > now) total += it->second;
  return total;
}

UploadShare AddressLimits::share_for(std::size_t held, std::size_t bytes) const {
  if (held > 0 && held + bytes > limits_.upload_bytes_per_address) return UploadShare::address_full;
  if (upload_bytes_ > 0 && upload_bytes_ + bytes > limits_.upload_bytes_total) return UploadShare::server_full;
  return UploadShare::granted;
}

UploadShare AddressLimits::upload_fits(const std::string& key, std::size_t bytes) const {
  std::lock_guard lock(mutex_);
  const auto it = entries_.find(key);
  return share_for(it == entries_.end() ? 0 : it->second.upload_bytes, bytes);
}

UploadShare AddressLimits::reserve_upload(const std::string& key, std::size_t bytes) {
  std::lock_guard lock(mutex_);
  const auto it = entries_.try_emplace(key).first;
  Entry& entry = it->second;
  if (const UploadShare share = share_for(entry.upload_bytes, bytes); share != UploadShare::granted) {
    forget_if_idle(it, Clock::now());
    return share;
  }
  entry.upload_bytes += bytes;
  upload_bytes_ += bytes;
  return UploadShare::granted;
}

void AddressLimits::release_upload(const std::string& key, std::size_t bytes) {
  std::lock_guard lock(mutex_);
  const auto it = entries_.find(key);
  if (it == entries_.end()) return;
  bytes = std::min(bytes, it->second.upload_bytes);
  it->second.upload_bytes -= bytes;
  upload_bytes_ -= std::min(bytes, upload_bytes_);
  forget_if_idle(it, Clock::now());
}

std::size_t AddressLimits::upload_bytes() const {
  std::lock_guard lock(mutex_);
  return upload_bytes_;
}

void AddressLimits::forget_if_idle(std::map<std::string, Entry>::iterator it, Clock::time_point now) {
  Entry& entry = it->second;
  if (entry.connections != 0 || entry.upload_bytes != 0) return;
  for (auto& bucket : entry.buckets)
    if (bucket && !bucket->full(now)) return;  // its limits still remember
  entries_.erase(it);
}

void AddressLimits::sweep(Clock::time_point now) {
  takes_since_sweep_ = 0;
  for (auto it = entries_.begin(); it != entries_.end();) forget_if_idle(it++, now);
}

}  // namespace fw::server
