#include "espeak_engine.hpp"
#include "fw/speech/espeak_data_folder.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <map>
#include <mutex>
#include <set>
#include <tuple>

#include <espeak-ng/speak_lib.h>

namespace fw::speech {
namespace {

// espeak-ng's state is process-wide (one voice, one callback, one set of
// buffers): this mutex is held from choosing the voice to the last event
// of a synthesis, and while starting espeak-ng.
std::mutex engine_mutex;

struct Engine {
  bool started = false;
  std::string start_error;
  int sample_rate_hz = 0;
  std::string data_folder;  ///< where espeak-ng reads its voice data
  std::map<std::string, std::string> voice_files;  ///< language -> its voice file, below data_folder
  std::set<std::string> languages;  ///< lower case, as the voice files name them
  std::map<std::string, std::string> names;  ///< language -> the name of the voice that speaks it best
};

// The synthesis in progress; the callback has no other way to find it
// (espeak-ng's user data is per event, and the end of audio has no event).
// Read and written only with engine_mutex held.
struct Collecting {
  SynthesisEvents* out = nullptr;
  std::size_t stop_after_samples = 0;
};
Collecting collecting;

std::string lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

int on_synthesis(short* wav, int sample_count, espeak_EVENT* events) {
  SynthesisEvents& out = *collecting.out;
  if (wav && sample_count > 0) out.samples.insert(out.samples.end(), wav, wav + sample_count);
  for (const espeak_EVENT* e = events; e && e->type != espeakEVENT_LIST_TERMINATED; ++e) {
    if (e->type == espeakEVENT_PHONEME) {
      // Up to 8 bytes, zero-terminated only when shorter.
      const std::size_t length = strnlen(e->id.string, sizeof e->id.string);
      out.phonemes.push_back({std::string(e->id.string, length), e->audio_position});
    } else if (e->type == espeakEVENT_WORD && e->text_position > 0) {
      // text_position counts code points from 1.
      out.words.push_back({static_cast<std::size_t>(e->text_position - 1), e->audio_position});
    }
  }
  return out.samples.size() > collecting.stop_after_samples ? 1 : 0;  // 1 stops the synthesis
}

// The file of the voice espeak_SetVoiceByProperties takes for each
// language: the first of espeak-ng's own ranking that is not an MBROLA
// voice (which SetVoiceByProperties passes over too). Called with
// engine_mutex held, after the list of all voices was read: each
// espeak_ListVoices call reuses the array the last one returned.
std::map<std::string, std::string> voice_files_of(const std::set<std::string>& languages) {
  std::map<std::string, std::string> files;
  for (const std::string& language : languages) {
    espeak_VOICE spec{};
    spec.languages = language.c_str();
    for (const espeak_VOICE** voice = espeak_ListVoices(&spec); voice && *voice; ++voice) {
      const std::string_view identifier = (*voice)->identifier ? (*voice)->identifier : "";
      if (identifier.empty() || identifier.starts_with("mb/")) continue;
      files[language] = "lang/" + std::string(identifier);  // identifiers name files below lang/
      break;
    }
  }
  return files;
}

// Called with engine_mutex held.
Engine& started_engine() {
  static Engine engine = [] {
    Engine e;
    // Synchronous: espeak_Synth returns when the audio is made, having
    // called on_synthesis on this thread. Phoneme events carry espeak-ng's
    // ASCII mnemonics (not IPA). DONT_EXIT: missing data is an error to
    // report, not a reason for espeak-ng to end the process.
    const int rate = espeak_Initialize(AUDIO_OUTPUT_SYNCHRONOUS, 0, nullptr,
                                       espeakINITIALIZE_PHONEME_EVENTS | espeakINITIALIZE_DONT_EXIT);
    if (rate <= 0) {
      e.start_error = "espeak-ng could not start (is espeak-ng-data installed? run deploy/install-deps.sh)";
      return e;
    }
    e.sample_rate_hz = rate;
    const char* path = nullptr;
    espeak_Info(&path);
    e.data_folder = path ? path : "";
    espeak_SetSynthCallback(on_synthesis);
    // For each language, the voice it is the first language of wins, then
    // the voice that gives it the lowest priority number (espeak-ng's best).
    std::map<std::string, std::tuple<bool, int>> rank;
    for (const espeak_VOICE** voice = espeak_ListVoices(nullptr); voice && *voice; ++voice) {
      // A list of (priority byte, name, zero byte), ended by an empty name.
      bool first = true;
      for (const char* entry = (*voice)->languages; entry && *entry; entry += std::strlen(entry) + 1) {
        const std::string language = lower(entry + 1);
        e.languages.insert(language);
        const std::tuple<bool, int> this_rank{!first, static_cast<unsigned char>(entry[0])};
        first = false;
        const auto known = rank.find(language);
        if (known != rank.end() && known->second <= this_rank) continue;
        rank[language] = this_rank;
        e.names[language] = (*voice)->name ? (*voice)->name : language;
      }
    }
    e.voice_files = voice_files_of(e.languages);
    e.started = true;
    return e;
  }();
  return engine;
}

std::string language_list(const std::set<std::string>& languages) {
  std::string list;
  for (const auto& language : languages) list += (list.empty() ? "" : ", ") + language;
  return list;
}

}  // namespace

bool espeak_synthesize(std::string_view text, std::string_view language, double stop_after_s,
                       SynthesisEvents& out, std::string& error) {
  const std::lock_guard lock(engine_mutex);
  Engine& engine = started_engine();
  if (!engine.started) {
    error = engine.start_error;
    return false;
  }
  const std::string wanted = lower(language);
  if (!engine.languages.contains(wanted)) {
    error = "no espeak-ng voice speaks the language '" + std::string(language) +
            "'; the installed voices speak: " + language_list(engine.languages);
    return false;
  }
  espeak_VOICE spec{};
  spec.languages = wanted.c_str();
  if (espeak_SetVoiceByProperties(&spec) != EE_OK) {
    error = "espeak-ng could not load its voice for '" + wanted + "'";
    return false;
  }
  out = SynthesisEvents{};
  out.sample_rate_hz = engine.sample_rate_hz;
  if (text.empty()) return true;
  collecting = {&out, static_cast<std::size_t>(std::max(0.0, stop_after_s) * engine.sample_rate_hz)};
  const std::string terminated(text);  // espeak-ng reads up to the zero byte
  const espeak_ERROR status = espeak_Synth(terminated.c_str(), terminated.size() + 1, 0, POS_CHARACTER, 0,
                                           espeakCHARS_UTF8, nullptr, nullptr);
  collecting = {};
  if (status != EE_OK) {
    error = "espeak-ng could not synthesise the text (error " + std::to_string(status) + ")";
    return false;
  }
  return true;
}

std::string espeak_data_folder() {
  const std::lock_guard lock(engine_mutex);
  return started_engine().data_folder;
}

std::map<std::string, std::string> espeak_voice_files() {
  const std::lock_guard lock(engine_mutex);
  return started_engine().voice_files;
}

std::map<std::string, std::string> espeak_languages() {
  const std::lock_guard lock(engine_mutex);
  return started_engine().names;
}

}  // namespace fw::speech
