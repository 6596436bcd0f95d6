#include "fw/speech/phoneme_timing.hpp"

#include <algorithm>

#include "espeak_engine.hpp"
#include "fw/speech/speakable_text.hpp"

namespace fw::speech {
namespace {

bool is_pause(const std::string& name) { return name.empty() || name.front() == '_'; }

// Where to cut speech longer than `max_ms`: the start of the last word that
// begins in time (its sound would be cut off), unless that is the first
// word, which is then cut at the limit itself.
struct Cut {
  int at_ms = 0;
  std::size_t first_unspoken_code_point = 0;
};
Cut cut_point(const SynthesisEvents& events, int max_ms) {
  Cut cut{max_ms, 0};
  for (std::size_t i = 1; i < events.words.size(); ++i) {
    if (events.words[i].start_ms > max_ms) break;
    cut = {events.words[i].start_ms, events.words[i].code_point};
  }
  if (cut.at_ms == max_ms && !events.words.empty()) cut.first_unspoken_code_point = events.words.front().code_point;
  return cut;
}

// A cut line's audio fades out over 10 ms rather than ending in a click.
void fade_out(std::vector<std::int16_t>& samples, int sample_rate_hz) {
  const std::size_t n = std::min(samples.size(), static_cast<std::size_t>(sample_rate_hz / 100));
  for (std::size_t i = 0; i < n; ++i) {
    auto& s = samples[samples.size() - 1 - i];
    s = static_cast<std::int16_t>(s * static_cast<double>(i) / static_cast<double>(n));
  }
}

// Cuts speech longer than `max_ms` at cut_point(): the audio (faded out),
// and how much of the text was said. Returns where, in milliseconds.
int cut(SynthesisEvents& events, int max_ms, std::string_view speakable, PhonemeTiming& out) {
  const Cut at = cut_point(events, max_ms);
  out.truncated = true;
  out.spoken_bytes = byte_offset_of_code_point(speakable, at.first_unspoken_code_point);
  // Up to the end of the last spoken word, not the spaces after it.
  while (out.spoken_bytes > 0 && speakable[out.spoken_bytes - 1] == ' ') --out.spoken_bytes;
  const auto samples = static_cast<std::size_t>(static_cast<double>(at.at_ms) * events.sample_rate_hz / 1000.0);
  events.samples.resize(std::min(events.samples.size(), samples));
  fade_out(events.samples, events.sample_rate_hz);
  return at.at_ms;
}

// Speakers open their mouths before the first sound (the mouth moves 100-300 ms
// ahead of the voice: Chandrasekaran et al., "The natural statistics of
// audiovisual speech", PLoS Comput. Biol. 5(7), 2009), where espeak-ng's
// audio starts with the sound. A short silence in front leaves a face that time.
void lead_with_silence(PhonemeTiming& timing) {
  const auto lead_samples = static_cast<std::size_t>(PhonemeTiming::kLeadS * timing.sample_rate_hz);
  const double lead_s = static_cast<double>(lead_samples) / timing.sample_rate_hz;
  for (auto& p : timing.phonemes) p.start_s += lead_s, p.end_s += lead_s;
  // The pause lasts until the first phoneme (espeak-ng's own audio may
  // start with a few milliseconds of silence).
  timing.phonemes.insert(timing.phonemes.begin(), TimedPhoneme{"_", 0.0, timing.phonemes.front().start_s});
  timing.samples.insert(timing.samples.begin(), lead_samples, 0);
}

}  // namespace

bool time_phonemes(std::string_view text, std::string_view language, const SpeechLimits& limits,
                   PhonemeTiming& out, std::string& error) {
  out = PhonemeTiming{};
  if (text.size() > SpeechLimits::kMaxTextBytes) {
    error = "the text is " + std::to_string(text.size()) + " bytes; at most " +
            std::to_string(SpeechLimits::kMaxTextBytes) + " are spoken: shorten it";
    return false;
  }
  // The language is checked even for silent text: a wrong one is the
  // caller's error whatever the line says.
  const std::string speakable = speakable_text(text);
  SynthesisEvents events;
  const std::string_view to_say = has_speech(speakable) ? std::string_view(speakable) : std::string_view();
  if (!espeak_synthesize(to_say, language, limits.max_seconds, events, error)) return false;
  out.sample_rate_hz = events.sample_rate_hz;
  const bool says_something = std::any_of(events.phonemes.begin(), events.phonemes.end(),
                                          [](const auto& p) { return !is_pause(p.name); });
  if (to_say.empty() || !says_something) return true;

  const int max_ms = static_cast<int>(limits.max_seconds * 1000.0);
  const auto audio_ms = static_cast<int>(1000.0 * static_cast<double>(events.samples.size()) / events.sample_rate_hz);
  int end_ms = audio_ms;
  out.spoken_bytes = text.size();
  if (audio_ms > max_ms) end_ms = cut(events, max_ms, speakable, out);
  const double end_s = static_cast<double>(events.samples.size()) / events.sample_rate_hz;
  for (std::size_t i = 0; i < events.phonemes.size() && events.phonemes[i].start_ms < end_ms; ++i) {
    const double next_s = i + 1 < events.phonemes.size() ? events.phonemes[i + 1].start_ms / 1000.0 : end_s;
    out.phonemes.push_back(
        {events.phonemes[i].name, std::min(events.phonemes[i].start_ms / 1000.0, end_s), std::min(next_s, end_s)});
  }
  out.samples = std::move(events.samples);
  lead_with_silence(out);
  return true;
}

}  // namespace fw::speech
