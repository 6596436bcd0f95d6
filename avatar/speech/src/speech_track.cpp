#include "fw/speech/speech_track.hpp"

#include <algorithm>
#include <cmath>

namespace fw::speech {

double SpeechTrack::length_s() const {
  return keys.empty() ? 0.0 : static_cast<double>(keys.size() - 1) * kKeyStepS;
}

AuTargets SpeechTrack::at(double t_s) const {
  if (keys.empty() || !(t_s >= 0.0) || t_s > length_s()) return AuTargets{};
  const double position = t_s / kKeyStepS;
  const std::size_t i = std::min(static_cast<std::size_t>(position), keys.size() - 1);
  if (i + 1 >= keys.size()) return keys.back();
  const float f = static_cast<float>(position - static_cast<double>(i));
  AuTargets out;
  for (std::size_t c = 0; c < out.size(); ++c) out[c] = keys[i][c] + f * (keys[i + 1][c] - keys[i][c]);
  return out;
}

std::vector<VisemeSegment> viseme_segments(std::span<const TimedPhoneme> phonemes) {
  std::vector<VisemeSegment> segments;
  for (const auto& phoneme : phonemes) {
    if (phoneme.end_s <= phoneme.start_s) continue;  // no time, no shape
    const auto visemes = visemes_of(phoneme.name);
    if (!visemes) continue;
    if (visemes->second == visemes->first) {
      segments.push_back({visemes->first, phoneme.start_s, phoneme.end_s});
    } else {
      const double middle = 0.5 * (phoneme.start_s + phoneme.end_s);
      segments.push_back({visemes->first, phoneme.start_s, middle});
      segments.push_back({visemes->second, middle, phoneme.end_s});
    }
  }
  return segments;
}

SpeechTrack speech_track(const PhonemeTiming& timing) {
  SpeechTrack track;
  track.truncated = timing.truncated;
  track.spoken_bytes = timing.spoken_bytes;
  if (timing.phonemes.empty()) return track;
  std::vector<VisemeSegment> segments = viseme_segments(timing.phonemes);
  // Silence around the line: the mouth comes from rest and returns to it.
  const double end_s = timing.length_s() + SpeechTrack::kCloseS;
  segments.insert(segments.begin(), {Viseme::rest, -0.2, segments.empty() ? 0.0 : segments.front().start_s});
  segments.push_back({Viseme::rest, segments.back().end_s, end_s + 0.2});
  const auto key_count = static_cast<std::size_t>(std::ceil(end_s / SpeechTrack::kKeyStepS)) + 1;
  track.keys.reserve(key_count);
  for (std::size_t k = 0; k < key_count; ++k)
    track.keys.push_back(coarticulate(segments, static_cast<double>(k) * SpeechTrack::kKeyStepS));
  // The ends are exactly still; the blend is all but still there (the
  // lead and kCloseS of rest), so no step shows.
  track.keys.front() = AuTargets{};
  track.keys.back() = AuTargets{};
  return track;
}

}  // namespace fw::speech
