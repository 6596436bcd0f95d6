#pragma once
// One encoder of a face whose frames go to several of its viewers at once.
//
// A room of n people held n^2 encoders, one per face per stream (each
// person's stream carries its own face too), and an encoder makes exactly
// the frames another one makes once both hold the same state, are offered
// the same face and are allowed the same bits. In the common room, viewers
// on links that keep up with alike budgets, every face was encoded n times
// over: the encoders were a fifth of a loaded server's time. So such viewers of a face share one encoder (a group): the
// first of them to be ticked encodes, the rest send the same bytes.
// ViewerEncoding decides who shares; this is the group.
//
// - Its budget is the least of its members' own: nobody is sent more than
//   its own budget allows. One allowed much more leaves (ViewerEncoding).
// - A viewer joins on a key frame, which the whole group receives (the
//   joiner's decoder holds nothing the group's predicted frames build on),
//   so a group takes new members at most once per second of ticks: a key
//   frame costs its members a few predicted frames' bits.
// - Every member offers every tick the same way (a frame or a hold): one
//   whose link needs something else this tick leaves, with an encoder of
//   its own starting on a key frame.
// - A group offered a tick out of turn (no member offered the one before,
//   or a room taken over counts its ticks afresh) is broken and every
//   member leaves: its clock would be off.
//
// Rooms' streams are not loss-tolerant (their decoders take a key frame at
// any point of the stream), which a viewer moving between encoders needs.
// Owned by its members, listed by the face's FaceEncoders; used on the
// room's strand only.
#include <cstdint>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "fw/codec/codec.hpp"

namespace fw::server {

/// What two viewers' encoders must have in common to make the same frames:
/// the encoder's clock and refresh rate, and the ticks on which their
/// streams take frames (every tick, or every bundle_ticks-th on a thin budget).
struct SharingKey {
  int tick_rate_hz = 0;
  int refresh_ticks = 0;
  std::uint32_t bundle_ticks = 1;
  bool operator==(const SharingKey&) const = default;
};

class SharedEncoder {
 public:
  /// A group founded by `member`, whose own encoder (in step with its
  /// viewer's decoder) becomes the group's: no key frame is needed.
  SharedEncoder(codec::Encoder encoder, const SharingKey& key, const void* member, double target_bps);

  /// Whether `key` and `target_bps` fit this group: the same key, and
  /// a budget that neither lowers the group's by more than kJoinLowering
  /// nor lies above kMaxBudgetRatio times it.
  bool fits(const SharingKey& key, double target_bps) const;
  /// Whether a member may join at `tick` (once per second of ticks; the
  /// tick of the last join too, so that viewers ready together share one key frame).
  bool takes_members_at(std::uint32_t tick) const;
  /// `member` joins: the group's next frame is a key frame.
  void join(const void* member, double target_bps, std::uint32_t tick);
  void leave(const void* member);
  void set_target(const void* member, double target_bps);
  /// A group of one goes wherever its member goes: a new key (its bundling
  /// changed), a key frame (its client asked for one).
  void rekey(const SharingKey& key) { key_ = key; }
  void force_key_frame() { encoder_.force_key_frame(); }
  const SharingKey& key() const { return key_; }
  double target_bps() const { return target_bps_; }
  std::size_t members() const { return members_.size(); }

  enum class Offer { frame, no_frame, diverged };
  /// Offers tick `tick`'s face: the first member offering a tick encodes
  /// it (`send`) or holds it, the others get the same outcome. `diverged`:
  /// this tick went the other way, or the group is broken; the member
  /// must leave. `reused` says whether the tick was already encoded.
  Offer offer(std::uint32_t tick, const codec::FaceSource& source, bool send, bool& reused);
  /// Whether the group has offered `tick` already.
  bool offered(std::uint32_t tick) const { return ran_ && tick_ == tick; }
  /// The frame of the last offered tick (valid until the next one).
  std::span<const std::uint8_t> frame() const { return frame_; }
  codec::EncoderStats stats() const { return encoder_.stats(); }

  /// A joiner may lower the group's budget by this share at most.
  static constexpr double kJoinLowering = 0.8;
  /// A member allowed more than this times the group's budget leaves.
  static constexpr double kMaxBudgetRatio = 1.5;

 private:
  void retarget();

  codec::Encoder encoder_;
  SharingKey key_;
  std::vector<std::pair<const void*, double>> members_;  ///< each member's own budget
  double target_bps_;
  bool ran_ = false, broken_ = false, sent_ = false, produced_ = false;
  std::uint32_t tick_ = 0;
  const codec::FaceSource* source_ = nullptr;  ///< the last offered tick's, and its count
  std::uint64_t source_ticks_ = 0;
  bool any_join_ = false;
  std::uint32_t last_join_tick_ = 0;
  std::vector<std::uint8_t> frame_;
};

/// A face's groups in its room (FaceSources keeps one per face).
class FaceEncoders {
 public:
  /// The group `key` and `target_bps` fit, or null.
  std::shared_ptr<SharedEncoder> find(const SharingKey& key, double target_bps);
  /// A new group (SharedEncoder's constructor), listed here.
  std::shared_ptr<SharedEncoder> found(codec::Encoder encoder, const SharingKey& key, const void* member,
                                       double target_bps);
  /// Groups that still have members.
  std::size_t groups();

 private:
  std::vector<std::weak_ptr<SharedEncoder>> groups_;  ///< members own them
};

}  // namespace fw::server
