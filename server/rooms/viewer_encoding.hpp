#pragma once
// One viewer's encoding of one face: an encoder of its own, or a place in a
// SharedEncoder with the face's other viewers whose frames would be the same
// (shared_encoder.hpp says why). Owned by the viewer's SubscriberStream.
//
// A viewer shares while its link keeps up: every tick it offers the face
// either for a frame or (a congested link, a message waiting, a bundled
// tick) to be held, and a group's members must all do the same. So:
// - it founds a group with its own encoder (no key frame: the group's
//   encoder is the one its decoder follows) when the face has none its
//   budget fits, or joins the one that fits on the group's next key frame
//   (waiting, on its own encoder, while the group took a member less than
//   a second ago);
// - it leaves as soon as its tick goes another way than the group's, its
//   budget is more than SharedEncoder::kMaxBudgetRatio times the group's,
//   the client asks for a key frame, or its bundling changes: then it
//   encodes on its own again, from a key frame, and offers to share again
//   kRejoinSeconds later at the earliest (a link that congests now and then
//   does not make its group send key frames over and over).
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "avatar_face.hpp"
#include "fw/codec/codec.hpp"
#include "shared_encoder.hpp"

namespace fw::server {

class ViewerEncoding {
 public:
  explicit ViewerEncoding(const codec::EncoderOptions& options);
  ~ViewerEncoding();
  ViewerEncoding(const ViewerEncoding&) = delete;
  ViewerEncoding& operator=(const ViewerEncoding&) = delete;

  void set_target_bps(double bits_per_second);
  /// The next frame this viewer receives is a key frame (a resync request).
  void force_key_frame();

  struct Offered {
    std::span<const std::uint8_t> frame;  ///< empty: no frame this tick; valid until the face's next tick
    bool reused = false;                  ///< encoded already, for another viewer
  };
  /// Offers tick `tick`'s face, for a frame (`send`) or to be held.
  /// `face.encoders` null (or no `face.source`): this viewer never shares.
  /// `bundle_ticks`: on how many ticks the viewer's stream takes frames.
  Offered offer(std::uint32_t tick, const AvatarFace& face, bool send, std::uint32_t bundle_ticks);

  /// The encoder's statistics (the group's when shared).
  codec::EncoderStats stats() const;
  /// Frames this viewer was sent.
  std::uint64_t frames_sent() const { return frames_sent_; }

  static constexpr double kRejoinSeconds = 2.0;

 private:
  SharingKey key(std::uint32_t bundle_ticks) const;
  /// Joins or founds a group at `tick` if the face has one that fits or none.
  void try_to_share(std::uint32_t tick, FaceEncoders& encoders, const SharingKey& key);
  /// Back to an encoder of its own, from a key frame.
  void leave(std::uint32_t tick);
  Offered offer_own(const AvatarFace& face, bool send);

  codec::EncoderOptions options_;  ///< target_bps: this viewer's own budget for the face
  std::optional<codec::Encoder> own_;  ///< null while in a group
  std::shared_ptr<SharedEncoder> group_;
  std::uint32_t share_from_tick_ = 0;  ///< no sharing before this tick
  std::uint32_t last_tick_ = 0;        ///< the last offered
  std::vector<std::uint8_t> frame_;
  std::uint64_t frames_sent_ = 0;
};

}  // namespace fw::server
