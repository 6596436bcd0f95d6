// Read aloud's sound (read_aloud.js decides what starts and stops when):
// each heard line is synthesised as soon as its speaking message arrives
// (../speech/espeak_voice.js, loaded the first time read aloud is turned
// on), its leading silence cut, and played with Web Audio at the place
// read_aloud.js gives it on the page's clock, mapped to the AudioContext's
// clock through getOutputTimestamp (which includes the output's latency),
// so the first phoneme is heard when the lips say it.
//
// `log` keeps, per line, when its frame was shown and when its sound was
// scheduled to be heard (performance.now ms), for whoever inspects the page.
import { EspeakVoice } from '../speech/espeak_voice.js';
import { ReadAloudSchedule, leadingSilence, placeSound } from './read_aloud.js';

const MAX_LOG = 50;

export class ReadAloudPlayer {
  /**
   * @param {object} options
   * @param {(avatar: number) => boolean} options.isMuted
   * @param {() => Promise<EspeakVoice>} [options.loadVoice]
   * @param {() => number} [options.now]  the page's clock (performance.now)
   * @param {(message: string) => void} [options.onProblem]  what went wrong, for the person
   */
  constructor({ isMuted, loadVoice = () => EspeakVoice.load(), now = () => performance.now(), onProblem = () => {} }) {
    this.schedule = new ReadAloudSchedule(isMuted);
    this.loadVoice = loadVoice;
    this.now = now;
    this.onProblem = onProblem;
    this.on = false;
    this.voice = null;      // Promise<EspeakVoice>, from the first enable()
    this.context = null;    // the AudioContext, from the first enable()
    this.analyser = null;   // every line's sound passes through it
    this.lines = new Map(); // id -> { line, sound: Promise, shownMs, source, cancelled }
    this.log = [];
  }

  /** Turns read aloud on (call it from a click: browsers start sound on a gesture). */
  enable() {
    this.on = true;
    if (!this.context) {
      this.context = new AudioContext();
      this.analyser = this.context.createAnalyser();
      this.analyser.connect(this.context.destination);
    }
    this.context.resume().catch(() => {});
    if (!this.voice) {
      this.voice = this.loadVoice();
      this.voice.catch((error) => {
        this.voice = null;  // turning it on again tries again
        this.onProblem(`read aloud could not start: ${error.message}`);
      });
    }
  }

  disable() {
    this.on = false;
    this.cancel(this.schedule.stopAll());
  }

  /** A speaking message arrived after `framesReceived` room frames. */
  heard(line, framesReceived) {
    if (!this.on || !this.voice) return;
    const id = this.schedule.heard(line, framesReceived);
    if (!id) return;
    const entry = { line, sound: this.synthesise(line), shownMs: null, source: null, cancelled: false };
    entry.sound.catch((error) => this.onProblem(`a line could not be read aloud: ${error.message}`));
    this.lines.set(id, entry);
  }

  /** The page drew the room as of `framesReceived` room frames, at `nowMs`. */
  shown(framesReceived, nowMs) {
    if (!this.on) return;
    const { start, cancel } = this.schedule.shown(framesReceived, nowMs);
    this.cancel(cancel);
    for (const { id, shownMs } of start) {
      const entry = this.lines.get(id);
      if (!entry) continue;
      entry.shownMs = shownMs;
      entry.sound.then((sound) => this.play(id, sound), () => this.lines.delete(id));
    }
  }

  /** The speaker left, or the viewer muted them. */
  silence(avatar) { this.cancel(this.schedule.silence(avatar)); }

  async synthesise(line) {
    const voice = await this.voice;
    const { samples, sampleRateHz } = await voice.synthesize(line.text, line.language);
    const first = leadingSilence(samples);
    const sound = samples.subarray(first);
    const buffer = this.context.createBuffer(1, Math.max(1, sound.length), sampleRateHz);
    const channel = buffer.getChannelData(0);
    for (let i = 0; i < sound.length; ++i) channel[i] = sound[i] / 32768;
    return { buffer, silenceMs: (first / sampleRateHz) * 1000, soundMs: (sound.length / sampleRateHz) * 1000 };
  }

  play(id, { buffer, silenceMs, soundMs }) {
    const entry = this.lines.get(id);
    if (!entry || entry.cancelled || !this.on) return;
    const nowMs = this.now();
    const place = placeSound({ shownMs: entry.shownMs, silenceMs, soundMs, nowMs });
    const record = { id, avatar: entry.line.avatar, language: entry.line.language, text: entry.line.text,
      durationMs: entry.line.durationMs, shownMs: entry.shownMs, silenceMs, soundMs, soundAtMs: null, offsetMs: 0 };
    this.remember(record);
    if (!place) {
      this.lines.delete(id);
      return;
    }
    let when = this.contextTimeAt(place.atMs, nowMs);
    let offsetS = place.offsetMs / 1000;
    if (when < this.context.currentTime) {  // the output's clock is past it already
      offsetS += this.context.currentTime - when;
      when = this.context.currentTime;
    }
    const source = this.context.createBufferSource();
    source.buffer = buffer;
    source.connect(this.analyser);
    source.onended = () => { if (this.lines.get(id)?.source === source) this.lines.delete(id); };
    source.start(when, offsetS);
    entry.source = source;
    record.soundAtMs = place.atMs + (offsetS * 1000 - place.offsetMs);
    record.offsetMs = offsetS * 1000;
  }

  /** The AudioContext time whose sound is heard at `atMs` on the page's clock. */
  contextTimeAt(atMs, nowMs) {
    const stamp = this.context.getOutputTimestamp?.();
    if (stamp && stamp.performanceTime > 0) return stamp.contextTime + (atMs - stamp.performanceTime) / 1000;
    return this.context.currentTime + (atMs - nowMs) / 1000 - (this.context.outputLatency || 0);
  }

  cancel(ids) {
    for (const id of ids) {
      const entry = this.lines.get(id);
      if (!entry) continue;
      entry.cancelled = true;
      try {
        entry.source?.stop();
      } catch {
        // never started, or over already
      }
      this.lines.delete(id);
    }
  }

  remember(record) {
    this.log.push(record);
    if (this.log.length > MAX_LOG) this.log.shift();
  }
}
