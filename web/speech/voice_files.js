// Which of espeak-ng's data files a language needs (the server serves its
// own espeak-ng data under /speech/data/NAME, server/PROTOCOL.md 8): the
// phoneme tables every voice shares, the language's voice file, and the
// dictionary that voice file names.

/** The phoneme tables, read when espeak-ng starts. */
export const PHONEME_TABLES = Object.freeze(['phontab', 'phonindex', 'phondata', 'intonations']);

/**
 * The dictionary a voice file makes espeak-ng load, as espeak-ng's
 * LoadVoice decides it: a `dictionary NAME` line, else the first
 * `language` line's code up to its first `-` ("en-us" -> "en").
 * @param {string} voiceText  the voice file (lang/CODE)
 * @returns {string} the data file's name ("en_dict"), or '' when the file names no language
 */
export function dictionaryOf(voiceText) {
  let fromLanguage = '';
  let named = '';
  for (const line of voiceText.split('\n')) {
    const [keyword, value] = line.trim().split(/\s+/);
    if (keyword === 'language' && value && !fromLanguage) fromLanguage = value.split('-')[0];
    if (keyword === 'dictionary' && value) named = value;
  }
  const dictionary = named || fromLanguage;
  return dictionary ? `${dictionary.toLowerCase()}_dict` : '';
}
