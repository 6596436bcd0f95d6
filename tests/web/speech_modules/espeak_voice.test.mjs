// The browser's read-aloud voice (web/speech) under node: espeak-ng's
// WebAssembly module (FW_SPEECH_MODULE_DIR, from the build) speaking from
// the voice data a real facewire-server serves (/speech/data/), as the room
// page does, held to the lengths the server's own espeak-ng gives the same
// lines (FW_SPEECH_DURATIONS, written by tests/speech/speech_durations.cpp);
// and which data files a language needs.
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';

import { EspeakVoice } from '../../../web/speech/espeak_voice.js';
import { dictionaryOf } from '../../../web/speech/voice_files.js';
import { startServer } from '../support/harness.mjs';

let server;
let voice;
const fetched = [];

before(async () => {
  const dir = process.env.FW_SPEECH_MODULE_DIR;
  assert.ok(dir, 'FW_SPEECH_MODULE_DIR names the built speech module (run through ctest)');
  server = await startServer(['--no-demo-room']);
  const fetchBytes = async (url) => {
    fetched.push(url);
    const response = await fetch(new URL(url, server.url));
    if (!response.ok) throw new Error(`${url}: HTTP ${response.status}`);
    return new Uint8Array(await response.arrayBuffer());
  };
  voice = await EspeakVoice.load({
    moduleUrl: join(dir, 'facewire_speech.js'), wasmBinary: readFileSync(join(dir, 'facewire_speech.wasm')), fetchBytes,
  });
});
after(async () => { await server?.stop(); });

test('a voice file names its dictionary, or its language does', () => {
  assert.equal(dictionaryOf('name English (America)\nlanguage en-us 2\nlanguage en 3\n'), 'en_dict');
  assert.equal(dictionaryOf('name Portuguese (Brazil)\nlanguage pt-br\nlanguage pt 6\n'), 'pt_dict');
  assert.equal(dictionaryOf('name Cantonese\nlanguage yue\ndictionary yue\n'), 'yue_dict');
  assert.equal(dictionaryOf('name Norwegian\nlanguage nb\ndictionary no\n'), 'no_dict');
  assert.equal(dictionaryOf('name nothing\n'), '');
});

test('espeak-ng says English and German lines from the server\'s data, each at its own length', async () => {
  assert.equal(voice.sampleRateHz, 22050);
  const english = await voice.synthesize('Hello there, how are you today?', 'en');
  const german = await voice.synthesize('Hallo, wie geht es dir heute?', 'de');
  for (const { samples } of [english, german]) {
    const seconds = samples.length / voice.sampleRateHz;
    assert.ok(seconds > 1 && seconds < 3, `${seconds} s for six words`);
    assert.ok(samples.some((s) => Math.abs(s) > 5000), 'it is heard');
  }
  assert.notEqual(english.samples.length, german.samples.length);
  // Only what the languages need was fetched: the tables, two voices, two dictionaries.
  const names = fetched.map((u) => u.replace('/speech/data/', '')).sort();
  assert.deepEqual(names, ['de_dict', 'en_dict', 'intonations', 'lang/de', 'lang/en', 'phondata', 'phonindex', 'phontab']);
});

test('the same line lasts the same again, whatever was said between', async () => {
  // espeak-ng's wave generator runs on from one line into the next (its
  // pitch periods, its noise), so a line may end a few samples off: within 1 ms.
  const a = await voice.synthesize('One more line.', 'en');
  await voice.synthesize('Ein anderer Satz.', 'de');
  const b = await voice.synthesize('One more line.', 'en');
  assert.ok(Math.abs(a.samples.length - b.samples.length) <= voice.sampleRateHz / 1000,
    `${a.samples.length} then ${b.samples.length} samples`);
});

test('every language the server lists has its voice file and dictionary served', async () => {
  const { languages } = await (await fetch(new URL('/api/languages', server.url))).json();
  assert.ok(languages.length > 20, `${languages.length} languages`);
  const missing = [];
  for (const { code } of languages) {
    const voiceFile = await fetch(new URL(`/speech/data/lang/${code}`, server.url));
    if (!voiceFile.ok) {
      missing.push(`lang/${code}`);
      continue;
    }
    const dictionary = dictionaryOf(await voiceFile.text());
    const served = await fetch(new URL(`/speech/data/${dictionary}`, server.url));
    await served.arrayBuffer();  // read, so that its connection is free for the next request
    if (!served.ok) missing.push(`${dictionary} (${code}): HTTP ${served.status}`);
  }
  assert.deepEqual(missing, []);
});

// The module is espeak-ng 1.52.0, the server's library 1.51 (web/README.md,
// "Read aloud"), on the same data: English comes out the same length, give
// or take the few milliseconds espeak-ng's state carries from one line into
// the next; the engine changed a little between the releases for some
// others (Spanish and Brazilian Portuguese 1.5 to 2 % shorter).
const LENGTH_TOLERANCE = { en: 0.01, 'en-us': 0.01 };
const OTHER_LANGUAGES_TOLERANCE = 0.04;

test("each line lasts in the browser what it lasts in the server's espeak-ng", async () => {
  const path = process.env.FW_SPEECH_DURATIONS;
  assert.ok(path, 'FW_SPEECH_DURATIONS names the lengths speech_durations wrote (run through ctest)');
  const lines = JSON.parse(readFileSync(path, 'utf8'));
  assert.ok(lines.length >= 5);
  for (const { language, text, sampleRateHz, samples } of lines) {
    assert.equal(sampleRateHz, voice.sampleRateHz);
    const ours = (await voice.synthesize(text, language)).samples.length;
    const off = Math.abs(ours - samples) / samples;
    const tolerance = LENGTH_TOLERANCE[language] ?? OTHER_LANGUAGES_TOLERANCE;
    console.log(`${language}: the server says '${text}' in ${(samples / sampleRateHz * 1000).toFixed(0)} ms, ` +
      `the browser in ${(ours / sampleRateHz * 1000).toFixed(0)} ms (${(off * 100).toFixed(2)} % apart)`);
    assert.ok(off <= tolerance, `${language}: ${ours} samples against the server's ${samples} (at most ${tolerance * 100} % apart)`);
  }
});

test('a language the server has no voice for is refused with its name', async () => {
  await assert.rejects(voice.synthesize('hello', 'xx'), /lang\/xx: HTTP 404/);
});
