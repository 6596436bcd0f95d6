// The grid's integers back to FaceParams values, and the rounding of a
// value to a coarser level's units (codec/src/quantiser.cpp).
import { CHANNELS } from './channel_table.js';

/** q in units of 2^shift steps, to the nearest (halves up: floor division, as the C++). */
export const roundToUnits = (q, shift) => (shift === 0 ? q : (q + (1 << (shift - 1))) >> shift);

/** FaceParams values from the field integers: float32(q * step), as the C++ decoder gives. */
export function dequantise(q) {
  const v = (c) => Math.fround(q[c] * CHANNELS[c].step);
  return {
    au: Array.from({ length: 29 }, (_, c) => v(c)),
    head_yaw_rad: v(29),
    head_pitch_rad: v(30),
    head_roll_rad: v(31),
    head_translation_mm: [v(32), v(33), v(34)],
    eye_left: { yaw_rad: v(35), pitch_rad: v(36) },
    eye_right: { yaw_rad: v(37), pitch_rad: v(38) },
    lid_left: v(39),
    lid_right: v(40),
    blush: [v(41), v(42), v(43), v(44), v(45)],
    pallor: v(46),
    corrective: Array.from({ length: 6 }, (_, k) => v(47 + k)),
  };
}
