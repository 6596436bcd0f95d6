#include "fw/behavior/conversation_gaze.hpp"

#include <algorithm>
#include <cmath>

namespace fw::behavior {
namespace {

bool sees(const std::vector<PerceivedFace>& seen, FaceId id) {
  return std::any_of(seen.begin(), seen.end(), [&](const PerceivedFace& f) { return f.id == id; });
}

}  // namespace

ConversationGaze::ConversationGaze(std::uint64_t seed) : rng_(seed) {}

double ConversationGaze::lognormal(double median) {
  return std::lognormal_distribution<double>(std::log(median), kSpread)(rng_);
}

void ConversationGaze::draw_away_offset() {
  std::uniform_real_distribution<double> unit(0, 1);
  const float amplitude = std::min(
      static_cast<float>(std::exponential_distribution<double>(1.0 / kAwayAmplitudeRad)(rng_)), kAwayAmplitudeMaxRad);
  // One of the four axes (0, 90, 180, 270 degrees) or of the four diagonals.
  const int quarter = std::uniform_int_distribution<int>(0, 3)(rng_);
  const double direction = 1.5707963 * quarter + (unit(rng_) < kAxisShare ? 0.0 : 0.7853982);
  away_offset_ = {amplitude * static_cast<float>(std::cos(direction)), amplitude * static_cast<float>(std::sin(direction))};
}

std::optional<ConversationLook> ConversationGaze::step(const ConversationScene& scene,
                                                       const std::vector<PerceivedFace>& seen) {
  if (scene.my_start_s) return speak(scene, seen);
  if (speech_start_s_ >= 0) {
    // This face's line just ended, looking at a listener (the end look):
    // it hands the turn over by holding that look a moment (Kendon 1967),
    // as its listeners hold theirs.
    speech_start_s_ = -1;
    handover_until_s_ = speaker_looking_ && listener_ ? scene.now_s + kAfterS : -1;
  }
  std::optional<ConversationLook> look = listen(scene, seen);
  if (!look && scene.now_s < handover_until_s_ && listener_ && sees(seen, *listener_))
    return ConversationLook{listener_, {}, {}};
  return look;
}

std::optional<ConversationLook> ConversationGaze::listen(const ConversationScene& scene,
                                                         const std::vector<PerceivedFace>& seen) {
  const double now = scene.now_s;
  if (!scene.speaker) {
    // The line ended: look a moment longer at whoever said it, then let go.
    if (listening_to_ && after_until_s_ < 0) after_until_s_ = now + kAfterS;
    if (listening_to_ && now < after_until_s_) return ConversationLook{listening_to_, {}, {}};
    listening_to_.reset();
    return std::nullopt;
  }
  after_until_s_ = -1;
  if (scene.speaker != listening_to_ || scene.speaker_start_s != listen_start_s_) {
    // A new speaker, or a new line: turn to it after this face's own latency.
    const bool new_speaker = scene.speaker != listening_to_;
    listening_to_ = scene.speaker;
    listen_start_s_ = scene.speaker_start_s;
    if (new_speaker) {
      const double latency = std::normal_distribution<double>(kLatencyS, kLatencySpreadS)(rng_);
      react_at_s_ = scene.speaker_start_s + std::clamp(latency, kLatencyMinS, kLatencyMaxS);
      looking_ = true;
      phase_until_s_ = react_at_s_ + lognormal(kListenGlanceS);
    }
  }
  // A speaker is heard wherever it sits: the listener turns to it even
  // from outside its view.
  if (now < react_at_s_) return std::nullopt;
  // The speaker looking at this listener: a listener looking away returns
  // the look (after a reaction time), and one whose glance would end holds
  // it a little longer; the speaker usually ends mutual gaze.
  const bool met = std::any_of(seen.begin(), seen.end(),
                               [&](const PerceivedFace& f) { return f.id == *listening_to_ && f.looks_at_me; });
  if (!looking_ && met && phase_until_s_ > now + kLatencyS) phase_until_s_ = now + kLatencyS;
  if (now >= phase_until_s_) {
    if (looking_ && met && now < phase_until_s_ + kHoldMutualS) return ConversationLook{listening_to_, {}, {}};
    looking_ = !looking_;
    phase_until_s_ = now + lognormal(looking_ ? kListenGlanceS : kListenAwayS);
    if (!looking_) draw_away_offset();
  }
  if (looking_) return ConversationLook{listening_to_, {}, {}};
  return ConversationLook{{}, listening_to_, away_offset_};
}

std::optional<FaceId> ConversationGaze::next_listener(const std::vector<PerceivedFace>& seen) {
  if (seen.empty()) return std::nullopt;
  // One who looks at the speaker first (a listener's look invites the
  // speaker's); else the nearest after the last one looked at.
  for (const PerceivedFace& f : seen)
    if (f.looks_at_me && f.id != listener_) return f.id;
  for (std::size_t i = 0; i < seen.size(); ++i)
    if (seen[i].id == listener_) return seen[(i + 1) % seen.size()].id;
  return seen.front().id;
}

std::optional<ConversationLook> ConversationGaze::speak(const ConversationScene& scene,
                                                        const std::vector<PerceivedFace>& seen) {
  const double now = scene.now_s;
  listening_to_.reset();
  if (seen.empty()) return std::nullopt;
  if (*scene.my_start_s != speech_start_s_) {
    speech_start_s_ = *scene.my_start_s;
    const bool long_line = scene.my_length_s.value_or(0) > kLongUtteranceS;
    speaker_looking_ = !(long_line && std::uniform_real_distribution<double>(0, 1)(rng_) < kStartAwayShare);
    speaker_phase_until_s_ = now + lognormal(speaker_looking_ ? kSpeakGlanceS : kSpeakAwayS);
    if (speaker_looking_ || !listener_ || !sees(seen, *listener_)) listener_ = next_listener(seen);
    if (!speaker_looking_) draw_away_offset();
  }
  const double ends_at = speech_start_s_ + scene.my_length_s.value_or(0);
  if (now >= ends_at - kEndLookS) {
    // Handing over: look at a listener as the line ends.
    if (!speaker_looking_) {
      speaker_looking_ = true;
      listener_ = next_listener(seen);
    }
    return ConversationLook{listener_, {}, {}};
  }
  // A glance the listener returns becomes mutual gaze, which the speaker
  // lets last its own while before it looks away.
  const bool met = speaker_looking_ && listener_ && std::any_of(seen.begin(), seen.end(), [&](const PerceivedFace& f) {
                     return f.id == *listener_ && f.looks_at_me;
                   });
  if (!met) mutual_until_s_ = -1;
  else if (mutual_until_s_ < 0) mutual_until_s_ = now + lognormal(kMutualS);
  if (now >= speaker_phase_until_s_ && !(met && now < mutual_until_s_)) {
    speaker_looking_ = !speaker_looking_;
    speaker_phase_until_s_ = now + lognormal(speaker_looking_ ? kSpeakGlanceS : kSpeakAwayS);
    if (speaker_looking_) listener_ = next_listener(seen);
    else draw_away_offset();
  }
  if (!listener_ || !sees(seen, *listener_)) listener_ = next_listener(seen);
  if (speaker_looking_) return ConversationLook{listener_, {}, {}};
  return ConversationLook{{}, listener_, away_offset_};
}

}  // namespace fw::behavior
