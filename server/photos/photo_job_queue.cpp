#include "photo_job_queue.hpp"

#include <algorithm>

#include "peer_address.hpp"

namespace fw::server {

PhotoJobQueue::PhotoJobQueue(std::size_t limit, std::size_t running_per_block)
    : limit_(limit), running_per_block_(std::max<std::size_t>(running_per_block, 1)),
      block_places_(std::max<std::size_t>(limit / 2 + limit % 2, 1)) {}

bool PhotoJobQueue::full_for(const std::string& owner) const {
  if (full()) return true;
  const auto block = blocks_.find(address_group(owner));
  return block != blocks_.end() && block->second.waiting_uploads >= block_places_;
}

bool PhotoJobQueue::push_bounded(const std::string& owner, Job job) {
  if (full_for(owner)) return false;
  add(owner, {std::move(job), true});
  ++blocks_[address_group(owner)].waiting_uploads;
  ++waiting_uploads_;
  return true;
}

void PhotoJobQueue::push(const std::string& owner, Job job) { add(owner, {std::move(job), false}); }

void PhotoJobQueue::add(const std::string& owner, Entry entry) {
  const std::string group = address_group(owner);
  auto& queue = jobs_[owner];
  if (queue.empty()) {
    Block& block = blocks_[group];
    if (block.turns.empty()) turns_.push_back(group);
    block.turns.push_back(owner);
  }
  queue.push_back(std::move(entry));
  ++waiting_;
}

std::optional<PhotoJobQueue::Next> PhotoJobQueue::next() const {
  for (auto group = turns_.begin(); group != turns_.end(); ++group) {
    const Block& block = blocks_.at(*group);
    if (block.running >= running_per_block_) continue;  // its photos in preparation go first
    for (auto owner = block.turns.begin(); owner != block.turns.end(); ++owner)
      if (!running_.contains(*owner)) return Next{group, owner};
  }
  return std::nullopt;
}

std::optional<PhotoJobQueue::Taken> PhotoJobQueue::take() {
  const auto found = next();
  if (!found) return std::nullopt;
  std::string group = *found->block;
  Block& block = blocks_.at(group);
  std::string owner = *found->owner;
  block.turns.erase(found->owner);
  turns_.erase(found->block);
  auto queued = jobs_.find(owner);
  Entry entry = std::move(queued->second.front());
  queued->second.pop_front();
  if (queued->second.empty())
    jobs_.erase(queued);
  else
    block.turns.push_back(owner);  // its next job waits for everyone else's in the block
  if (!block.turns.empty()) turns_.push_back(group);  // the block's next job waits for the other blocks
  --waiting_;
  if (entry.bounded) {
    --waiting_uploads_;
    --block.waiting_uploads;
  }
  ++block.running;
  ++running_[owner];
  ++running_total_;
  return Taken{std::move(owner), std::move(entry.job)};
}

bool PhotoJobQueue::ready() const { return next().has_value(); }

void PhotoJobQueue::finished(const std::string& owner) {
  const auto it = running_.find(owner);
  if (it == running_.end()) return;
  if (--it->second == 0) running_.erase(it);
  --running_total_;
  const auto block = blocks_.find(address_group(owner));
  if (block == blocks_.end()) return;
  --block->second.running;
  if (block->second.running == 0 && block->second.turns.empty() && block->second.waiting_uploads == 0)
    blocks_.erase(block);
}

}  // namespace fw::server
