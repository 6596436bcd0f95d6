// What the decoder shows between frames (codec/src/reconstruction.cpp,
// FORMAT.md "Prediction"): each channel's value and velocity in sub-steps,
// its damping and the ticks since its update, extrapolated at most
// `maxExtrapolationTicks`. The encoder runs the same arithmetic, which is
// why it must be integer for integer the C++'s.
import { CHANNELS, CHANNEL_COUNT, SUB_STEPS, SUB_STEP_BITS, clamp, damp } from './channel_table.js';

export class Reconstruction {
  constructor(maxExtrapolationTicks) {
    this.limit = maxExtrapolationTicks;
    this.value = new Array(CHANNEL_COUNT).fill(0); // sub-steps
    this.velocity = new Array(CHANNEL_COUNT).fill(0); // sub-steps per tick
    this.dampingClass = new Array(CHANNEL_COUNT).fill(0);
    this.age = new Array(CHANNEL_COUNT).fill(0);
  }
  clone() {
    const r = new Reconstruction(this.limit);
    r.value = this.value.slice();
    r.velocity = this.velocity.slice();
    r.dampingClass = this.dampingClass.slice();
    r.age = this.age.slice();
    return r;
  }
  advance(ticks) {
    for (let c = 0; c < CHANNEL_COUNT; c++) this.age[c] = Math.min(this.age[c] + ticks, this.limit);
  }
  /** Channel `c`'s coded value (grid steps) `extra` ticks after now. */
  shown(c, extra = 0) {
    const ticks = Math.min(this.age[c] + extra, this.limit);
    let v = this.value[c];
    if (this.dampingClass[c] === 0) {
      v += this.velocity[c] * ticks;
    } else {
      let w = this.velocity[c];
      for (let i = 0; i < ticks && w !== 0; i++) {
        v += w;
        w = damp(w, this.dampingClass[c]);
      }
    }
    const ch = CHANNELS[c];
    v = clamp(v, ch.codedMin * SUB_STEPS, ch.codedMax * SUB_STEPS);
    return (v + SUB_STEPS / 2) >> SUB_STEP_BITS;
  }
  set(c, q, velocity, dampingClass) {
    this.value[c] = q * SUB_STEPS;
    this.velocity[c] = velocity;
    this.dampingClass[c] = dampingClass;
    this.age[c] = 0;
  }
  /** Holds the face still where it is shown now (after a lost or refused frame). */
  freeze() {
    const shown = Array.from({ length: CHANNEL_COUNT }, (_, c) => this.shown(c));
    for (let c = 0; c < CHANNEL_COUNT; c++) this.set(c, shown[c], 0, 0);
  }
}
