#pragma once
// The chat lines an avatar says, in turn, each in its writer's language:
// the lines that arrive while the avatar is still speaking (or while its
// next line's lip-sync track is being made) wait, a few at most; when the
// avatar's turn comes, its next line is handed out to have its track made
// (track_maker.hpp), and it is said once that track is back.
//
// Limits: kMaxWaiting lines wait per avatar; a further line is shown as
// chat but not said. A line longer than speech::SpeechLimits::max_seconds
// is said in part (the track says how much). Both are told in the room's
// events ("speech: ...").
// Not thread-safe: the room's strand, like RoomSimulation.
#include <array>
#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fw/codec/face_params.hpp"

namespace fw::server {

/// A line to say now: its text, the language it is said in, its lip-sync
/// track (empty when espeak-ng cannot say it: the face speaks for the
/// line's estimated length with a still mouth), how much of the text the
/// track says, and what the events should tell.
struct LineToSay {
  /// One pose of the mouth's action units (avatar/speech's AuTargets).
  using Pose = std::array<float, codec::kAuChannelCount>;
  static constexpr double kPoseStepS = 0.01;  ///< speech::SpeechTrack::kKeyStepS

  std::string text;
  std::string language;
  std::vector<Pose> mouth;     ///< at 0, kPoseStepS, ...
  std::size_t said_bytes = 0;  ///< of `text`: all of it, or less when said in part
  std::string note;            ///< "" or, e.g., "said in part: 40 of 212 bytes (15 s at most)"
};

/// `text` said in `language`: its lip-sync track made with espeak-ng (tens
/// of milliseconds for a long line: make it off the room's strand,
/// track_maker.hpp). Thread-safe.
LineToSay make_line(std::string text, std::string language);

/// A line whose turn came: its track is to be made, then handed back with
/// its ticket (SpokenLines::made).
struct LineJob {
  std::uint32_t avatar = 0;
  std::uint64_t ticket = 0;
  std::string text;
  std::string language;
};

class SpokenLines {
 public:
  static constexpr std::size_t kMaxWaiting = 3;

  /// A line from `avatar`, to be said in `language`; false when too many of
  /// its lines wait already (the line is not said).
  bool add(std::uint32_t avatar, std::string text, std::string language);
  /// The next line of `avatar` to make a track for, if one waits, the avatar
  /// is not speaking and no line of its is being made.
  std::optional<LineJob> next(std::uint32_t avatar, bool speaking);
  /// The track of the line `ticket` is back (or will never come): true if
  /// that line is still to be said (its avatar is here and it was not forgotten).
  bool made(std::uint32_t avatar, std::uint64_t ticket);
  /// The avatar left: its waiting lines go, and a track on its way is dropped.
  void forget(std::uint32_t avatar) { avatars_.erase(avatar); }
  /// Avatars with lines waiting.
  std::vector<std::uint32_t> with_lines() const;

 private:
  struct Lines {
    std::deque<std::pair<std::string, std::string>> waiting;  ///< text, language
    std::uint64_t making = 0;  ///< the ticket of the line whose track is on its way; 0: none
  };
  std::map<std::uint32_t, Lines> avatars_;
  std::uint64_t next_ticket_ = 1;
};

}  // namespace fw::server
