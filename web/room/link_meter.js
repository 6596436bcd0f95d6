// What the room's link carries, for the meter: bits per second over the
// last few seconds, and decoded frames per second for each avatar. Counted
// from what actually arrived (every byte of every message).

export class LinkMeter {
  constructor(windowMs = 3000) {
    this.windowMs = windowMs;
    this.bytes = [];   // [timeMs, bytes]
    this.frames = new Map();  // avatar -> [timeMs]
    this.totalBytes = 0;
  }
  received(nowMs, bytes) {
    this.bytes.push([nowMs, bytes]);
    this.totalBytes += bytes;
    this.trim(nowMs);
  }
  frameDecoded(nowMs, avatar) {
    if (!this.frames.has(avatar)) this.frames.set(avatar, []);
    this.frames.get(avatar).push(nowMs);
  }
  forget(avatar) { this.frames.delete(avatar); }
  trim(nowMs) {
    const since = nowMs - this.windowMs;
    while (this.bytes.length && this.bytes[0][0] < since) this.bytes.shift();
    for (const times of this.frames.values()) while (times.length && times[0] < since) times.shift();
  }
  /** { kbps, fps: Map(avatar -> frames/s) } over the window ending at nowMs. */
  reading(nowMs) {
    this.trim(nowMs);
    const seconds = this.windowMs / 1000;
    const bits = this.bytes.reduce((sum, [, n]) => sum + n * 8, 0);
    const fps = new Map([...this.frames].map(([avatar, times]) => [avatar, times.length / seconds]));
    return { kbps: bits / seconds / 1000, fps };
  }
}
