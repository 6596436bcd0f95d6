// Sends a face lab's overrides no faster than the server's message rate
// allows (PROTOCOL.md 7: 50 messages a second, bursts of 100, pings
// included): a slider dragged fires input events at the screen's rate, and
// only its newest value matters. Each override (by what it sets) keeps its
// newest value, and what waits goes out at most every `intervalMs`.
export class OverrideSender {
  /**
   * @param send         (override) => void: one command on the wire
   * @param intervalMs   the least time between two sends of waiting overrides
   * @param setTimer     (fn, ms) => handle, clearTimer(handle): the clock (tests pass their own)
   */
  constructor({
    send, intervalMs = 50, now = () => performance.now(),
    setTimer = (fn, ms) => setTimeout(fn, ms), clearTimer = (handle) => clearTimeout(handle),
  }) {
    Object.assign(this, { send, intervalMs, now, setTimer, clearTimer });
    this.waiting = new Map();  // what it sets -> the newest override
    this.lastSentMs = -Infinity;
    this.timer = null;
  }

  /** The newest value of what `override` sets; sent at once, or at the next interval. */
  set(override) {
    this.waiting.set(`${override.part}/${override.index}/${override.side}`, override);
    const wait = this.lastSentMs + this.intervalMs - this.now();
    if (wait <= 0) this.flush();
    else if (this.timer === null) this.timer = this.setTimer(() => this.flush(), wait);
  }

  /** Sends `override` at once, dropping what waits (a reset: nothing sent later may undo it). */
  sendInstead(override) {
    this.waiting.clear();
    if (this.timer !== null) this.clearTimer(this.timer);
    this.timer = null;
    this.lastSentMs = this.now();
    this.send(override);
  }

  flush() {
    if (this.timer !== null) this.clearTimer(this.timer);
    this.timer = null;
    if (this.waiting.size === 0) return;
    this.lastSentMs = this.now();
    const waiting = [...this.waiting.values()];
    this.waiting.clear();
    for (const override of waiting) this.send(override);
  }
}
