// Integers as a zero flag, a sign and an adaptive Elias-gamma magnitude
// (codec/src/integer_coding.cpp, FORMAT.md "Integers").
import { AdaptiveBit, adaptiveBits } from './adaptive_bit.js';

export const MAX_MAGNITUDE_CLASS = 17;

/** The adaptive models of one kind of integer. */
export class IntegerModel {
  constructor() {
    this.zero = new AdaptiveBit();
    this.sign = new AdaptiveBit();
    this.prefix = adaptiveBits(MAX_MAGNITUDE_CLASS);
  }
}
export const integerModels = (n) => Array.from({ length: n }, () => new IntegerModel());

function readMagnitude(rc, model) {
  let k = 0;
  while (k < MAX_MAGNITUDE_CLASS - 1 && rc.bit(model.prefix[k]) === 1) k++;
  return 2 ** k + rc.raw(k);
}

export function decodeSigned(rc, model) {
  if (rc.bit(model.zero) === 0) return 0;
  const negative = rc.bit(model.sign) === 1;
  const m = readMagnitude(rc, model);
  return negative ? -m : m;
}

export function decodeUnsigned(rc, model) {
  if (rc.bit(model.zero) === 0) return 0;
  return readMagnitude(rc, model);
}
