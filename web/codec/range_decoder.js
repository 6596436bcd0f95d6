// The binary range decoder (codec/src/range_decoder.cpp, FORMAT.md "Range
// coder"). Past the payload's end it reads zeros, as the C++ does, and its
// error sticks: a frame is read to the end and judged once.
import { PROB_BITS } from './adaptive_bit.js';
import { DecodeError } from './decode_error.js';

export class RangeDecoder {
  constructor(bytes) {
    this.bytes = bytes;
    this.pos = 0;
    this.range = 0xffffffff;
    this.code = 0;
    this.error = DecodeError.ok;
    for (let i = 0; i < 4; i++) this.code = ((this.code << 8) | this.next()) >>> 0;
    if (this.code >= this.range) this.fail(DecodeError.checkFailed);
  }
  next() {
    return this.pos < this.bytes.length ? this.bytes[this.pos++] : 0;
  }
  normalise() {
    while (this.range < 0x1000000) {
      this.range = this.range * 256;
      this.code = ((this.code << 8) | this.next()) >>> 0;
    }
  }
  /** One bit with adaptive model `model` (an AdaptiveBit), which learns it. */
  bit(model) {
    const bound = (this.range >>> PROB_BITS) * model.p0;
    let b = 0;
    if (this.code < bound) {
      this.range = bound;
    } else {
      this.code -= bound;
      this.range -= bound;
      b = 1;
    }
    model.update(b);
    this.normalise();
    return b;
  }
  /** `count` equiprobable bits, most significant first. */
  raw(count) {
    let value = 0;
    for (let i = 0; i < count; i++) {
      const half = this.range >>> 1;
      let b = 0;
      if (this.code < half) {
        this.range = half;
      } else {
        this.code -= half;
        this.range -= half;
        b = 1;
      }
      value = value * 2 + b;
      this.normalise();
    }
    return value;
  }
  /** Keeps the first error. */
  fail(error) {
    if (this.error === DecodeError.ok) this.error = error;
  }
}
