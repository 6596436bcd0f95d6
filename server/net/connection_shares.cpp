#include "connection_shares.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace fw::server {

ConnectionShares::Verdict ConnectionShares::admit(const std::string& address, const std::string& block,
                                                  Clock::time_point now, bool must_evict) {
  Verdict verdict;
  std::function<void()> evict;
  {
    std::lock_guard lock(mutex_);
    const std::size_t held = block.empty() ? 0 : (blocks_.contains(block) ? blocks_.at(block) : 0);
    if (!block.empty() && held >= limits_.per_block) {
      verdict.refusal = Abuse::block_connection_limit;
      verdict.retry_after = wait_until_free(now, &block);
      return verdict;
    }
    // A block that holds none may take the reserve too: whoever comes from
    // a network that is not already here finds a place.
    const std::size_t reserve = std::min(limits_.fresh_reserve, limits_.max_total);
    const std::size_t places = held == 0 ? limits_.max_total : limits_.max_total - reserve;
    if (must_evict || open_ >= places) {
      const auto it = victim(held);
      if (it == entries_.end()) {
        verdict.refusal = must_evict ? Abuse::descriptors_exhausted : Abuse::connection_limit;
        verdict.retry_after = wait_until_free(now, nullptr);
        return verdict;
      }
      Entry& given_up = it->second;
      given_up.evicted = true;
      --open_;
      if (--blocks_[given_up.block] == 0) blocks_.erase(given_up.block);
      verdict.evicted = given_up.address;
      evict = given_up.evict;
    }
    verdict.id = next_id_++;
    entries_.emplace(verdict.id, Entry{address, block, now, now + limits::kHeaderTimeout, true, false, {}});
    ++open_;
    if (!block.empty()) ++blocks_[block];
  }
  if (evict) evict();
  return verdict;
}

std::map<ConnectionShares::Id, ConnectionShares::Entry>::iterator ConnectionShares::victim(std::size_t newcomer_holds) {
  auto chosen = entries_.end();
  std::size_t chosen_holds = 0;
  for (auto it = entries_.begin(); it != entries_.end(); ++it) {
    const Entry& entry = it->second;
    // A trusted proxy's connection carries other people's: never given up.
    if (!entry.waiting || entry.evicted || entry.block.empty()) continue;
    const std::size_t holds = blocks_.at(entry.block);
    // Only for a newcomer whose block would still hold fewer: one of the
    // crowd does not push out another (or a person on a fresh address).
    if (holds <= newcomer_holds + 1) continue;
    if (chosen == entries_.end() || holds > chosen_holds ||
        (holds == chosen_holds && entry.since < chosen->second.since)) {
      chosen = it;
      chosen_holds = holds;
    }
  }
  return chosen;
}

std::chrono::seconds ConnectionShares::wait_until_free(Clock::time_point now, const std::string* block) const {
  auto earliest = Clock::time_point::max();
  for (const auto& [id, entry] : entries_)
    if (!entry.evicted && (!block || entry.block == *block)) earliest = std::min(earliest, entry.deadline);
  if (earliest == Clock::time_point::max()) return kUnknownWait;
  const double seconds = std::chrono::duration<double>(earliest - now).count();
  return std::chrono::seconds(std::max<long>(1, static_cast<long>(std::ceil(seconds))));
}

std::chrono::seconds ConnectionShares::retry_for_address(const std::string& address, Clock::time_point now) const {
  std::lock_guard lock(mutex_);
  auto earliest = Clock::time_point::max();
  for (const auto& [id, entry] : entries_)
    if (!entry.evicted && entry.address == address) earliest = std::min(earliest, entry.deadline);
  if (earliest == Clock::time_point::max()) return kUnknownWait;
  const double seconds = std::chrono::duration<double>(earliest - now).count();
  return std::chrono::seconds(std::max<long>(1, static_cast<long>(std::ceil(seconds))));
}

void ConnectionShares::waiting(Id id, Clock::time_point now, Clock::time_point deadline) {
  std::lock_guard lock(mutex_);
  const auto it = entries_.find(id);
  if (it == entries_.end()) return;
  if (!it->second.waiting) it->second.since = now;
  it->second.waiting = true;
  it->second.deadline = deadline;
}

void ConnectionShares::busy(Id id, Clock::time_point deadline) {
  std::lock_guard lock(mutex_);
  const auto it = entries_.find(id);
  if (it == entries_.end()) return;
  it->second.waiting = false;
  it->second.deadline = deadline;
}

void ConnectionShares::on_evict(Id id, std::function<void()> evict) {
  {
    std::lock_guard lock(mutex_);
    const auto it = entries_.find(id);
    if (it == entries_.end()) return;
    if (!it->second.evicted) {
      it->second.evict = std::move(evict);
      return;
    }
  }
  evict();  // it gave its place up before its session could say how to close it
}

void ConnectionShares::release(Id id) {
  std::lock_guard lock(mutex_);
  const auto it = entries_.find(id);
  if (it != entries_.end()) forget(it);
}

void ConnectionShares::forget(std::map<Id, Entry>::iterator it) {
  const Entry& entry = it->second;
  if (!entry.evicted) {
    --open_;
    if (!entry.block.empty())
      if (const auto block = blocks_.find(entry.block); block != blocks_.end() && --block->second == 0)
        blocks_.erase(block);
  }
  entries_.erase(it);
}

std::size_t ConnectionShares::open() const {
  std::lock_guard lock(mutex_);
  return open_;
}

std::size_t ConnectionShares::held_by_block(const std::string& block) const {
  std::lock_guard lock(mutex_);
  const auto it = blocks_.find(block);
  return it == blocks_.end() ? 0 : it->second;
}

}  // namespace fw::server
