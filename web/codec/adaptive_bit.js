// The probability model of one binary decision (codec/src/adaptive_bit.cpp,
// FORMAT.md "Adaptive binary models"): it adapts fast at first, then
// slower, and never reaches certainty, so a surprise costs bits, not a
// broken stream.

export const PROB_BITS = 15;
const PROB_ONE = 1 << PROB_BITS;
const PROB_MIN = 32;
const ADAPTATION_STEPS = 62;
const clamp = (v, lo, hi) => (v < lo ? lo : v > hi ? hi : v);

export class AdaptiveBit {
  constructor() {
    this.p0 = PROB_ONE / 2;
    this.seen = 0;
  }
  update(bit) {
    const shift = Math.min(31 - Math.clz32(this.seen + 2), 6);
    let p = this.p0;
    if (bit === 0) p += (PROB_ONE - p) >> shift;
    else p -= p >> shift;
    this.p0 = clamp(p, PROB_MIN, PROB_ONE - PROB_MIN);
    if (this.seen < ADAPTATION_STEPS) this.seen += 1;
  }
}

/** `n` fresh models. */
export const adaptiveBits = (n) => Array.from({ length: n }, () => new AdaptiveBit());
