#include "shared_encoder.hpp"

#include <algorithm>

namespace fw::server {

SharedEncoder::SharedEncoder(codec::Encoder encoder, const SharingKey& key, const void* member, double target_bps)
    : encoder_(std::move(encoder)), key_(key), members_{{member, target_bps}}, target_bps_(target_bps) {
  encoder_.set_target_bps(target_bps_);
}

bool SharedEncoder::fits(const SharingKey& key, double target_bps) const {
  return !broken_ && key == key_ && target_bps >= kJoinLowering * target_bps_ &&
         target_bps <= kMaxBudgetRatio * target_bps_;
}

bool SharedEncoder::takes_members_at(std::uint32_t tick) const {
  const auto interval = static_cast<std::uint32_t>(std::max(1, key_.tick_rate_hz));
  return !any_join_ || tick == last_join_tick_ || tick - last_join_tick_ >= interval;
}

void SharedEncoder::join(const void* member, double target_bps, std::uint32_t tick) {
  members_.emplace_back(member, target_bps);
  any_join_ = true;
  last_join_tick_ = tick;
  encoder_.force_key_frame();
  retarget();
}

void SharedEncoder::leave(const void* member) {
  std::erase_if(members_, [member](const auto& m) { return m.first == member; });
  if (!members_.empty()) retarget();
}

void SharedEncoder::set_target(const void* member, double target_bps) {
  for (auto& m : members_)
    if (m.first == member) m.second = target_bps;
  retarget();
}

void SharedEncoder::retarget() {
  double least = members_.front().second;
  for (const auto& m : members_) least = std::min(least, m.second);
  if (least != target_bps_) {
    target_bps_ = least;
    encoder_.set_target_bps(least);
  }
}

SharedEncoder::Offer SharedEncoder::offer(std::uint32_t tick, const codec::FaceSource& source, bool send,
                                          bool& reused) {
  reused = false;
  if (broken_) return Offer::diverged;
  if (ran_ && tick == tick_ && (&source != source_ || source.ticks() != source_ticks_)) {
    // The same tick number from another source: the room was taken over
    // and counts afresh. This tick's frame is not the one encoded before.
    broken_ = true;
    return Offer::diverged;
  }
  if (ran_ && tick == tick_) {
    if (send != sent_) return Offer::diverged;
    reused = true;
    return produced_ ? Offer::frame : Offer::no_frame;
  }
  if (ran_ && tick != tick_ + 1) {
    // Nobody offered the ticks between: the encoder's clock lags its
    // members' decoders by them.
    broken_ = true;
    return Offer::diverged;
  }
  ran_ = true;
  tick_ = tick;
  source_ = &source;
  source_ticks_ = source.ticks();
  sent_ = send;
  if (send) {
    produced_ = encoder_.encode(source, frame_);
  } else {
    encoder_.hold(source);
    produced_ = false;
  }
  if (!produced_) frame_.clear();
  return produced_ ? Offer::frame : Offer::no_frame;
}

std::shared_ptr<SharedEncoder> FaceEncoders::find(const SharingKey& key, double target_bps) {
  for (const auto& weak : groups_)
    if (auto group = weak.lock(); group && group->fits(key, target_bps)) return group;
  return nullptr;
}

std::shared_ptr<SharedEncoder> FaceEncoders::found(codec::Encoder encoder, const SharingKey& key, const void* member,
                                                   double target_bps) {
  std::erase_if(groups_, [](const auto& weak) { return weak.expired(); });
  auto group = std::make_shared<SharedEncoder>(std::move(encoder), key, member, target_bps);
  groups_.push_back(group);
  return group;
}

std::size_t FaceEncoders::groups() {
  std::erase_if(groups_, [](const auto& weak) { return weak.expired(); });
  return groups_.size();
}

}  // namespace fw::server
