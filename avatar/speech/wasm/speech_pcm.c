/* The browser's speech synthesis (web/speech): espeak-ng, compiled to
 * WebAssembly, says a line in a voice into 16-bit PCM in memory. It is the
 * same synthesiser the server's avatar/speech drives for the lips, fed the
 * same voice data (the server serves its espeak-ng data folder under
 * /speech/data/), so the sound lasts what the lips last.
 *
 * The page writes the data files into the module's in-memory file system
 * under /espeak-ng-data/ before calling fw_speech_init, and one voice file
 * per language under /espeak-ng-data/lang/. One synthesis at a time: the
 * module is single-threaded, as the page is. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <espeak-ng/speak_lib.h>

/* The samples of the last synthesis, grown as espeak-ng hands them over. */
static int16_t* samples;
static size_t sample_count;
static size_t sample_capacity;
static int sample_rate_hz;

static int collect(short* wav, int count, espeak_EVENT* events) {
  (void)events;
  if (!wav || count <= 0) return 0;
  if (sample_count + (size_t)count > sample_capacity) {
    size_t capacity = sample_capacity ? sample_capacity : 16384;
    while (capacity < sample_count + (size_t)count) capacity *= 2;
    int16_t* grown = realloc(samples, capacity * sizeof *samples);
    if (!grown) return 1; /* out of memory: stop here, what was made is kept */
    samples = grown;
    sample_capacity = capacity;
  }
  memcpy(samples + sample_count, wav, (size_t)count * sizeof *samples);
  sample_count += (size_t)count;
  return 0;
}

/* Starts espeak-ng on the data under /espeak-ng-data; the sample rate in
 * hertz, or 0 when the data is missing or unreadable. */
int fw_speech_init(void) {
  /* Synchronous: espeak_Synth returns once the audio is made, having handed
   * it to collect (the server starts espeak-ng the same way). DONT_EXIT:
   * missing data is an error for the page to show, not a reason to abort. */
  const int rate = espeak_Initialize(AUDIO_OUTPUT_SYNCHRONOUS, 0, "/", espeakINITIALIZE_DONT_EXIT);
  if (rate <= 0) return 0;
  espeak_SetSynthCallback(collect);
  sample_rate_hz = rate;
  return rate;
}

/* Chooses the voice that speaks `language` (lower case, "en", "pt-br"), as
 * the server does (by its properties, among the voice files present). 0 on
 * success, espeak-ng's error otherwise. */
int fw_speech_set_language(const char* language) {
  /* espeak-ng lists the voice files once and keeps the list; the page adds
   * a language's file when it is first needed, so list them again. */
  espeak_ListVoices(NULL);
  espeak_VOICE spec;
  memset(&spec, 0, sizeof spec);
  spec.languages = language;
  return espeak_SetVoiceByProperties(&spec);
}

/* Says `text` (UTF-8, zero-terminated) in the chosen voice at espeak-ng's
 * default rate. The number of samples made (fw_speech_samples), or -1 when
 * espeak-ng failed. */
int fw_speech_synthesize(const char* text) {
  sample_count = 0;
  const espeak_ERROR status =
      espeak_Synth(text, strlen(text) + 1, 0, POS_CHARACTER, 0, espeakCHARS_UTF8, NULL, NULL);
  return status == EE_OK ? (int)sample_count : -1;
}

/* The last synthesis's samples, mono, at fw_speech_init's rate; valid
 * until the next synthesis. */
const int16_t* fw_speech_samples(void) { return samples; }

int fw_speech_sample_rate(void) { return sample_rate_hz; }
