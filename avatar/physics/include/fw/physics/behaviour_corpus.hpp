#pragma once
// A corpus of behaviour: sequences of action-unit targets at 30 Hz as a
// room's behaviour produces them (avatar/physics/corpus/, recorded by
// facewire-corpus), on which the corrective basis is fitted and measured.
//
// Text, one frame a line, so that a change shows in a diff and the files
// stay small (most channels hold still from one frame to the next):
//
//   # comment
//   sequence NAME            a new sequence; every channel starts at 0
//   3:250 12:1000            a frame: the channels that changed, channel:thousandths
//   3:250 pitch:-35          ... and the head's turn, if it changed: yaw:, pitch:
//                            and roll: in milliradians (HeadPose's signs)
//   .                        a frame where nothing changed
//
// Channels are FaceParams' action-unit channels (codec::kAuChannels order).
// The head's turn loads the tissue (head_loads.hpp); its slow sway of a
// few millimetres is not recorded (it loads the tissue by under 0.1 % of
// gravity).
#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "fw/codec/face_params.hpp"
#include "fw/physics/head_loads.hpp"

namespace fw::physics {

inline constexpr double kCorpusFrameS = 1.0 / 30.0;
// What a corpus file may hold; a reader refuses more.
inline constexpr std::size_t kMaxCorpusSequences = 256;
inline constexpr std::size_t kMaxCorpusFrames = 30 * 3600;  ///< an hour, over all sequences
inline constexpr std::size_t kMaxCorpusBytes = 16u << 20;

using AuFrame = std::array<float, codec::kAuChannelCount>;

/// The most a corpus head turns, radians, each way (codec::FaceParams' yaw
/// range; its pitch and roll ranges are narrower).
inline constexpr float kMaxCorpusHeadRad = 1.2f;

struct CorpusSequence {
  std::string name;             ///< letters, digits, '-' and '_', at most 64
  std::vector<AuFrame> frames;  ///< each channel in [0,1], steps of 1/1000
  /// The head's turn at each frame (as many as frames, or none: upright),
  /// steps of 1/1000 rad; no translation.
  std::vector<HeadPose> heads;
  HeadPose head(std::size_t frame) const { return frame < heads.size() ? heads[frame] : HeadPose{}; }
};

struct BehaviourCorpus {
  std::vector<CorpusSequence> sequences;
  std::size_t frame_count() const;
};

/// The corpus as text (values rounded to thousandths).
std::string write_behaviour_corpus(const BehaviourCorpus& corpus);
/// Parses a corpus; on failure `corpus` is untouched and `error` gives the
/// line and what was wrong there.
bool read_behaviour_corpus(std::string_view text, BehaviourCorpus& corpus, std::string& error);
/// Reads the file at `path` (at most kMaxCorpusBytes); `error` names it.
bool load_behaviour_corpus(const std::string& path, BehaviourCorpus& corpus, std::string& error);

}  // namespace fw::physics
