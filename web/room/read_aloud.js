// When each spoken line is heard (server/PROTOCOL.md 5.15), without sound,
// DOM or clocks of its own, so that node can test it: a speaking message
// says "this line starts with the next room frame"; the line's sound starts
// when the page shows that frame, a lead after it (the face opens its mouth
// before the voice, as the server's lip track does), and stops when the
// speaker's next line starts, the speaker leaves or is muted, or read aloud
// is turned off. Lines of avatar 0 (nobody's) and of muted people are not
// heard. The page (read_aloud_player.js) does the sound.

/**
 * The silence the server's lip track puts before a line's first sound
 * (avatar/speech PhonemeTiming::kLeadS): speakers open their mouths 100-300
 * ms before the voice (Chandrasekaran et al., "The natural statistics of
 * audiovisual speech", PLoS Comput. Biol. 5(7), 2009).
 */
export const LEAD_MS = 150;

/** Below this a sample is espeak-ng's leading silence: 1 % of full scale (-40 dBFS). */
export const SILENCE_LEVEL = 328;

/** Lines heard but not started yet that are kept: a hidden page draws no
 * frames, so none starts, and each holds its synthesised sound. */
export const MAX_WAITING_LINES = 8;

export class ReadAloudSchedule {
  /** @param {(avatar: number) => boolean} isMuted  whether the viewer muted this avatar now */
  constructor(isMuted = () => false) {
    this.isMuted = isMuted;
    this.nextId = 1;
    this.pending = [];          // { id, line, afterFrame }: heard, their first frame not shown yet
    this.dropped = [];          // ids of waiting lines let go for newer ones, to cancel at the next frame
    this.playing = new Map();   // id -> { avatar, endMs }
  }

  /**
   * A speaking message, received when `framesReceived` room frames had been:
   * its line starts with the next one. Returns the line's id (to synthesise
   * it ahead), or 0 for a line that is never heard.
   */
  heard(line, framesReceived) {
    if (line.avatar === 0 || this.isMuted(line.avatar)) return 0;
    const id = this.nextId++;
    this.pending.push({ id, line, afterFrame: framesReceived });
    if (this.pending.length > MAX_WAITING_LINES) this.dropped.push(this.pending.shift().id);
    return id;
  }

  /**
   * The page shows the room as of `framesReceived` room frames, at `nowMs`.
   * @returns {{start: {id: number, line: object, shownMs: number}[], cancel: number[]}}
   *   the lines whose first frame this is, and the lines they cut short
   */
  shown(framesReceived, nowMs) {
    const start = [];
    const cancel = this.dropped;
    this.dropped = [];
    for (const [id, p] of this.playing) if (p.endMs <= nowMs) this.playing.delete(id);
    const due = this.pending.filter((p) => p.afterFrame < framesReceived);
    this.pending = this.pending.filter((p) => p.afterFrame >= framesReceived);
    for (const { id, line } of due) {
      if (this.isMuted(line.avatar)) {
        cancel.push(id);  // muted since it was heard: its synthesis is let go
        continue;
      }
      cancel.push(...this.stopSpeaker(line.avatar));
      this.playing.set(id, { avatar: line.avatar, endMs: nowMs + line.durationMs });
      start.push({ id, line, shownMs: nowMs });
    }
    // Of one speaker's lines due at the same frame, only the last is heard.
    return { start: start.filter((s) => this.playing.has(s.id)), cancel };
  }

  /** The speaker left the room, or was muted: what of theirs to stop. */
  silence(avatar) {
    const cancel = this.pending.filter((p) => p.line.avatar === avatar).map((p) => p.id);
    this.pending = this.pending.filter((p) => p.line.avatar !== avatar);
    return [...cancel, ...this.stopSpeaker(avatar)];
  }

  /** Read aloud off, or the viewer leaves: everything to stop. */
  stopAll() {
    const cancel = [...this.dropped, ...this.pending.map((p) => p.id), ...this.playing.keys()];
    this.pending = [];
    this.dropped = [];
    this.playing.clear();
    return cancel;
  }

  stopSpeaker(avatar) {
    const cancel = [];
    for (const [id, p] of this.playing) {
      if (p.avatar !== avatar) continue;
      this.playing.delete(id);
      cancel.push(id);
    }
    return cancel;
  }
}

/** The index of the first sample louder than `level`: espeak-ng's leading silence ends there. */
export function leadingSilence(samples, level = SILENCE_LEVEL) {
  const i = samples.findIndex((s) => Math.abs(s) > level);
  return i < 0 ? samples.length : i;
}

/**
 * Where a line's sound goes on the page's clock: its first phoneme
 * `LEAD_MS` + `silenceMs` (the leading silence cut from the samples) after
 * the frame that started the line was shown. Sound ready late starts at
 * once, that much into the samples, so it stays in step with the lips.
 * @returns {{atMs: number, offsetMs: number} | null}  null when it would all be over
 */
export function placeSound({ shownMs, silenceMs, soundMs, nowMs }) {
  const atMs = shownMs + LEAD_MS + silenceMs;
  if (atMs >= nowMs) return { atMs, offsetMs: 0 };
  const offsetMs = nowMs - atMs;
  return offsetMs < soundMs ? { atMs: nowMs, offsetMs } : null;
}
