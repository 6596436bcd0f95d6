// The read-aloud synthesiser: espeak-ng compiled to WebAssembly
// (avatar/speech/wasm, served at /speech/facewire_speech.js and .wasm),
// speaking from the server's own voice data (/speech/data/NAME), so that a
// line lasts here what the speaker's lips last. Everything is fetched on the
// first use only: a person who never turns read aloud on loads nothing.
//
// Samples are copied out of the module's memory, which may grow.
import { PHONEME_TABLES, dictionaryOf } from './voice_files.js';

const MODULE_URL = new URL('./facewire_speech.js', import.meta.url).href;
const DATA = '/espeak-ng-data';

async function fetchBytes(url) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: HTTP ${response.status} (${(await response.text()).trim()})`);
  return new Uint8Array(await response.arrayBuffer());
}

export class EspeakVoice {
  /**
   * Loads the module and the phoneme tables, and starts espeak-ng.
   * @param {object} [options]
   * @param {string} [options.dataUrl]     where the voice data is served ('/speech/data/')
   * @param {string} [options.moduleUrl]   facewire_speech.js (default: beside this file)
   * @param {Uint8Array} [options.wasmBinary]  the .wasm bytes, when not fetched beside the module (node tests)
   * @param {(url: string) => Promise<Uint8Array>} [options.fetchBytes]  how data files are fetched
   */
  static async load({ dataUrl = '/speech/data/', moduleUrl = MODULE_URL, wasmBinary, fetchBytes: fetcher = fetchBytes } = {}) {
    const { default: createFacewireSpeech } = await import(moduleUrl);
    const [module, tables] = await Promise.all([
      createFacewireSpeech(wasmBinary ? { wasmBinary } : {}),
      Promise.all(PHONEME_TABLES.map((name) => fetcher(dataUrl + name))),
    ]);
    module.FS.mkdirTree(`${DATA}/lang`);
    PHONEME_TABLES.forEach((name, i) => module.FS.writeFile(`${DATA}/${name}`, tables[i]));
    const sampleRateHz = module._fw_speech_init();
    if (sampleRateHz <= 0) throw new Error('espeak-ng could not start on the voice data the server sent');
    return new EspeakVoice(module, sampleRateHz, dataUrl, fetcher);
  }

  constructor(module, sampleRateHz, dataUrl, fetcher) {
    this.module = module;
    this.sampleRateHz = sampleRateHz;
    this.dataUrl = dataUrl;
    this.fetcher = fetcher;
    this.languages = new Map();  // code -> Promise of its files being in place
  }

  /** Fetches what `language` needs (its voice file, its dictionary), once. */
  prepare(language) {
    if (!this.languages.has(language)) {
      const ready = (async () => {
        const voice = await this.fetcher(`${this.dataUrl}lang/${language}`);
        const dictionary = dictionaryOf(new TextDecoder().decode(voice));
        if (!dictionary) throw new Error(`the voice file of '${language}' names no language`);
        const dictionaryPath = `${DATA}/${dictionary}`;
        if (!this.module.FS.analyzePath(dictionaryPath).exists) {
          this.module.FS.writeFile(dictionaryPath, await this.fetcher(this.dataUrl + dictionary));
        }
        this.module.FS.writeFile(`${DATA}/lang/${language}`, voice);
      })();
      ready.catch(() => this.languages.delete(language));  // a failure may be tried again later
      this.languages.set(language, ready);
    }
    return this.languages.get(language);
  }

  /**
   * Says `text` in `language` at espeak-ng's default rate.
   * @returns {Promise<{samples: Int16Array, sampleRateHz: number}>} mono PCM
   */
  async synthesize(text, language) {
    await this.prepare(language);
    const m = this.module;
    const status = this.withString(language, (pointer) => m._fw_speech_set_language(pointer));
    if (status !== 0) throw new Error(`espeak-ng has no voice for '${language}' (error ${status})`);
    const count = this.withString(text, (pointer) => m._fw_speech_synthesize(pointer));
    if (count < 0) throw new Error(`espeak-ng could not say the line in '${language}'`);
    const start = m._fw_speech_samples() >>> 1;
    return { samples: m.HEAP16.slice(start, start + count), sampleRateHz: this.sampleRateHz };
  }

  withString(text, use) {
    const m = this.module;
    const size = m.lengthBytesUTF8(text) + 1;
    const pointer = m._malloc(size);
    try {
      m.stringToUTF8(text, pointer, size);
      return use(pointer);
    } finally {
      m._free(pointer);
    }
  }
}
