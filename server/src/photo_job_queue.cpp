#include "photo_job_queue.hpp"

namespace fw::server {

bool PhotoJobQueue::push_bounded(const std::string& owner, Job job) {
  if (full()) return false;
  add(owner, {std::move(job), true});
  ++waiting_uploads_;
  return true;
}

void PhotoJobQueue::push(const std::string& owner, Job job) { add(owner, {std::move(job), false}); }

void PhotoJobQueue::add(const std::string& owner, Entry entry) {
  auto& queue = jobs_[owner];
  if (queue.empty()) turns_.push_back(owner);
  queue.push_back(std::move(entry));
  ++waiting_;
}

std::optional<PhotoJobQueue::Taken> PhotoJobQueue::take() {
  for (auto turn = turns_.begin(); turn != turns_.end(); ++turn) {
    if (running_.contains(*turn)) continue;  // its photo in preparation goes first
    std::string owner = std::move(*turn);
    turns_.erase(turn);
    auto queued = jobs_.find(owner);
    Entry entry = std::move(queued->second.front());
    queued->second.pop_front();
    if (queued->second.empty())
      jobs_.erase(queued);
    else
      turns_.push_back(owner);  // its next job waits for everyone else's turn
    --waiting_;
    if (entry.bounded) --waiting_uploads_;
    ++running_[owner];
    ++running_total_;
    return Taken{std::move(owner), std::move(entry.job)};
  }
  return std::nullopt;
}

bool PhotoJobQueue::ready() const {
  for (const auto& owner : turns_)
    if (!running_.contains(owner)) return true;
  return false;
}

void PhotoJobQueue::finished(const std::string& owner) {
  const auto it = running_.find(owner);
  if (it == running_.end()) return;
  if (--it->second == 0) running_.erase(it);
  --running_total_;
}

}  // namespace fw::server
