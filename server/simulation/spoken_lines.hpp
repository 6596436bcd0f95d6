#pragma once
// The chat lines an avatar says, in turn: each line's lip-sync track made
// with espeak-ng (avatar/speech) when its turn comes, and the lines that
// arrive while the avatar is still speaking kept waiting, a few at most.
//
// Limits: kMaxWaiting lines wait per avatar; a further line is shown as
// chat but not said. A line longer than speech::SpeechLimits::max_seconds
// is said in part (the track says how much). Both are told in the room's
// events ("speech: ...").
// Not thread-safe: the room's strand, like RoomSimulation.
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fw/behavior/facs_track.hpp"

namespace fw::server {

/// A line to say now: its text, its lip-sync track (none when espeak-ng
/// cannot say it: the face speaks for the line's estimated length with a
/// still mouth), and what the events should tell.
struct LineToSay {
  std::string text;
  std::optional<behavior::AuTrack> mouth;
  std::string note;  ///< "" or, e.g., "said in part: 40 of 212 bytes (15 s at most)"
};

/// The lip-sync track of `text` in `language`; none and `note` when it
/// cannot be made (an unknown language, nothing to say).
std::optional<behavior::AuTrack> lip_sync_track(std::string_view text, const std::string& language, std::string& note);

class SpokenLines {
 public:
  static constexpr std::size_t kMaxWaiting = 3;

  explicit SpokenLines(std::string language) : language_(std::move(language)) {}

  /// A line from `avatar`; false when too many of its lines wait already
  /// (the line is not said).
  bool add(std::uint32_t avatar, std::string text);
  /// The next line of `avatar`, if one waits and the avatar is not speaking.
  std::optional<LineToSay> next(std::uint32_t avatar, bool speaking);
  /// The avatar left: its waiting lines go.
  void forget(std::uint32_t avatar) { waiting_.erase(avatar); }
  std::vector<std::uint32_t> with_lines() const;

 private:
  std::string language_;
  std::map<std::uint32_t, std::deque<std::string>> waiting_;
};

}  // namespace fw::server
