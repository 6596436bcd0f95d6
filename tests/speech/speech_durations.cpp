// Writes how long the server's espeak-ng (libespeak-ng, through
// fw::speech::time_phonemes) says a few lines in a few languages, as JSON,
// for the browser's read-aloud voice (web/speech, espeak-ng compiled to
// WebAssembly) to be held to: tests/web/speech_modules compare their own
// lengths with these (ctest fixture speech_durations).
//   speech_durations OUT.json
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "fw/speech/phoneme_timing.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: speech_durations OUT.json\n");
    return 2;
  }
  struct Line {
    const char* language;
    const char* text;
  };
  const Line lines[] = {
      {"en", "Hello there, how are you today?"},
      {"en-us", "Shall we meet again on Monday morning?"},
      {"de", "Guten Tag, wie geht es Ihnen heute?"},
      {"fr", "Bonjour, comment allez-vous aujourd'hui?"},
      {"es", "Buenos días, ¿cómo está usted hoy?"},
      {"pt-br", "Olá, tudo bem com você?"},
  };
  nlohmann::json out = nlohmann::json::array();
  for (const Line& line : lines) {
    fw::speech::PhonemeTiming timing;
    std::string error;
    if (!fw::speech::time_phonemes(line.text, line.language, fw::speech::SpeechLimits{}, timing, error)) {
      std::fprintf(stderr, "speech_durations: %s: %s\n", line.language, error.c_str());
      return 1;
    }
    // The audio is the lip track's lead of silence, then espeak-ng's own samples.
    const auto lead = static_cast<std::size_t>(fw::speech::PhonemeTiming::kLeadS * timing.sample_rate_hz);
    out.push_back({{"language", line.language},
                   {"text", line.text},
                   {"sampleRateHz", timing.sample_rate_hz},
                   {"samples", timing.samples.size() - lead}});
  }
  std::ofstream(argv[1]) << out.dump(2) << "\n";
  return 0;
}
