#include "spoken_lines.hpp"

#include "fw/speech/phoneme_timing.hpp"
#include "fw/speech/speech_track.hpp"

namespace fw::server {

std::optional<behavior::AuTrack> lip_sync_track(std::string_view text, const std::string& language, std::string& note) {
  speech::PhonemeTiming timing;
  std::string error;
  if (!speech::time_phonemes(text, language, speech::SpeechLimits{}, timing, error)) {
    note = "not said: " + error;
    return std::nullopt;
  }
  const speech::SpeechTrack track = speech::speech_track(timing);
  if (track.empty()) return std::nullopt;  // nothing to say (emoji alone): no note needed
  if (track.truncated)
    note = "said in part: " + std::to_string(track.spoken_bytes) + " of " + std::to_string(text.size()) +
           " bytes (" + std::to_string(static_cast<int>(speech::SpeechLimits{}.max_seconds)) + " s at most)";
  behavior::AuTrack mouth;
  mouth.times_s.reserve(track.keys.size());
  for (std::size_t i = 0; i < track.keys.size(); ++i) mouth.times_s.push_back(static_cast<double>(i) * speech::SpeechTrack::kKeyStepS);
  mouth.poses.assign(track.keys.begin(), track.keys.end());
  return mouth;
}

bool SpokenLines::add(std::uint32_t avatar, std::string text) {
  std::deque<std::string>& lines = waiting_[avatar];
  if (lines.size() >= kMaxWaiting) return false;
  lines.push_back(std::move(text));
  return true;
}

std::optional<LineToSay> SpokenLines::next(std::uint32_t avatar, bool speaking) {
  const auto it = waiting_.find(avatar);
  if (speaking || it == waiting_.end() || it->second.empty()) return std::nullopt;
  LineToSay line;
  line.text = std::move(it->second.front());
  it->second.pop_front();
  if (it->second.empty()) waiting_.erase(it);
  line.mouth = lip_sync_track(line.text, language_, line.note);
  return line;
}

std::vector<std::uint32_t> SpokenLines::with_lines() const {
  std::vector<std::uint32_t> avatars;
  for (const auto& [avatar, lines] : waiting_) avatars.push_back(avatar);
  return avatars;
}

}  // namespace fw::server
