#include "viewer_encoding.hpp"

#include <cmath>

namespace fw::server {

ViewerEncoding::ViewerEncoding(const codec::EncoderOptions& options)
    : options_(options), own_(std::in_place, options) {}

ViewerEncoding::~ViewerEncoding() {
  if (group_) group_->leave(this);
}

void ViewerEncoding::set_target_bps(double bits_per_second) {
  options_.target_bps = bits_per_second;
  if (own_) own_->set_target_bps(bits_per_second);
  if (group_) group_->set_target(this, bits_per_second);
}

void ViewerEncoding::force_key_frame() {
  if (own_) {
    own_->force_key_frame();
    if (group_) {
      // A join still to come would send the group's key frame next: this
      // viewer waits for it on its own encoder instead.
      group_->leave(this);
      group_.reset();
    }
    return;
  }
  // Its group's members need no key frame: it leaves (its own encoder
  // starts on one) and shares again later; alone, it keeps the encoder.
  if (group_->members() == 1) group_->force_key_frame();
  else leave(last_tick_);
}

SharingKey ViewerEncoding::key(std::uint32_t bundle_ticks) const {
  return {options_.stream.tick_rate_hz, options_.refresh_ticks, bundle_ticks};
}

void ViewerEncoding::leave(std::uint32_t tick) {
  group_->leave(this);
  group_.reset();
  own_.emplace(options_);  // starts on a key frame
  const auto rejoin = static_cast<std::uint32_t>(std::lround(kRejoinSeconds * options_.stream.tick_rate_hz));
  share_from_tick_ = tick + rejoin;
}

void ViewerEncoding::try_to_share(std::uint32_t tick, FaceEncoders& encoders, const SharingKey& key) {
  if (auto group = encoders.find(key, options_.target_bps)) {
    // Its next frame is a key frame for all: this tick's, unless a member
    // offered this tick already (then this viewer's own encoder makes this
    // tick's frame, and the group's key frame comes next tick).
    if (!group->takes_members_at(tick)) return;
    group->join(this, options_.target_bps, tick);
    group_ = std::move(group);
    if (!group_->offered(tick)) own_.reset();
    return;
  }
  // None fits: this viewer's encoder becomes a group's, in step with its decoder.
  group_ = encoders.found(std::move(*own_), key, this, options_.target_bps);
  own_.reset();
}

ViewerEncoding::Offered ViewerEncoding::offer(std::uint32_t tick, const AvatarFace& face, bool send,
                                              std::uint32_t bundle_ticks) {
  last_tick_ = tick;
  const bool can_share = face.encoders != nullptr && face.source != nullptr;
  const SharingKey wanted = key(bundle_ticks);
  if (group_ && own_) own_.reset();  // joined last tick: the group's key frame is next
  if (group_ && group_->members() == 1) group_->rekey(wanted);
  if (group_ && (!can_share || !(group_->key() == wanted) ||
                 options_.target_bps > SharedEncoder::kMaxBudgetRatio * group_->target_bps()))
    leave(tick);
  if (!group_ && can_share && send && tick >= share_from_tick_) try_to_share(tick, *face.encoders, wanted);
  if (own_) return offer_own(face, send);

  bool reused = false;
  switch (group_->offer(tick, *face.source, send, reused)) {
    case SharedEncoder::Offer::frame:
      ++frames_sent_;
      return {group_->frame(), reused};
    case SharedEncoder::Offer::no_frame:
      return {{}, reused};
    case SharedEncoder::Offer::diverged:
      break;
  }
  leave(tick);
  return offer_own(face, send);
}

ViewerEncoding::Offered ViewerEncoding::offer_own(const AvatarFace& face, bool send) {
  codec::Encoder& encoder = *own_;
  const codec::FaceSource* source = face.source;
  if (!send) {
    if (source != nullptr) encoder.hold(*source);
    else encoder.hold(*face.face);
    return {};
  }
  const bool produced = source != nullptr ? encoder.encode(*source, frame_) : encoder.encode(*face.face, frame_);
  if (!produced) return {};
  ++frames_sent_;
  return {frame_, false};
}

codec::EncoderStats ViewerEncoding::stats() const { return own_ ? own_->stats() : group_->stats(); }

}  // namespace fw::server
