#include "spoken_lines.hpp"

#include "fw/speech/phoneme_timing.hpp"
#include "fw/speech/speech_track.hpp"

namespace fw::server {

LineToSay make_line(std::string text, std::string language) {
  static_assert(LineToSay::kPoseStepS == speech::SpeechTrack::kKeyStepS);
  LineToSay line{std::move(text), std::move(language), {}, 0, {}};
  speech::PhonemeTiming timing;
  std::string error;
  if (!speech::time_phonemes(line.text, line.language, speech::SpeechLimits{}, timing, error)) {
    line.note = "not said: " + error;
    return line;
  }
  const speech::SpeechTrack track = speech::speech_track(timing);
  if (track.empty()) return line;  // nothing to say (emoji alone): no note needed
  line.said_bytes = track.truncated ? track.spoken_bytes : line.text.size();
  if (track.truncated)
    line.note = "said in part: " + std::to_string(track.spoken_bytes) + " of " + std::to_string(line.text.size()) +
                " bytes (" + std::to_string(static_cast<int>(speech::SpeechLimits{}.max_seconds)) + " s at most)";
  line.mouth.assign(track.keys.begin(), track.keys.end());
  return line;
}

bool SpokenLines::add(std::uint32_t avatar, std::string text, std::string language) {
  Lines& lines = avatars_[avatar];
  if (lines.waiting.size() >= kMaxWaiting) return false;
  lines.waiting.emplace_back(std::move(text), std::move(language));
  return true;
}

std::optional<LineJob> SpokenLines::next(std::uint32_t avatar, bool speaking) {
  const auto it = avatars_.find(avatar);
  if (speaking || it == avatars_.end() || it->second.waiting.empty() || it->second.making != 0) return std::nullopt;
  Lines& lines = it->second;
  LineJob job{avatar, next_ticket_++, std::move(lines.waiting.front().first),
              std::move(lines.waiting.front().second)};
  lines.waiting.pop_front();
  lines.making = job.ticket;
  return job;
}

bool SpokenLines::made(std::uint32_t avatar, std::uint64_t ticket) {
  const auto it = avatars_.find(avatar);
  if (it == avatars_.end() || it->second.making != ticket) return false;
  it->second.making = 0;
  if (it->second.waiting.empty()) avatars_.erase(it);
  return true;
}

std::vector<std::uint32_t> SpokenLines::with_lines() const {
  std::vector<std::uint32_t> avatars;
  for (const auto& [avatar, lines] : avatars_)
    if (!lines.waiting.empty()) avatars.push_back(avatar);
  return avatars;
}

}  // namespace fw::server
