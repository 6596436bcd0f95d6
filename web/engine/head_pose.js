// Head and eye matrices, as avatar/render/src/camera.cpp makes them
// (head_transform, eye_transform): column-major Float32Array(16), glm's and
// GLSL's layout. A port, not the same code (the renderer is not part of the
// WebAssembly module), so tests/model/wasm checks it against matrices the
// C++ wrote.
import { mat4 } from '../shared/mat4.js';

/** The point heads turn about (model/head_pose.hpp): the top of the neck. */
export const NECK_PIVOT = [0, -1.5, 0.2];
/** Millimetres per model unit (model::kMillimetresPerUnit): head translation is in mm. */
export const MILLIMETRES_PER_UNIT = 63;

// Float64 throughout: the matrices are compared with the C++'s.
export const identity = () => mat4.identity(Float64Array);
export const multiply = (a, b) => mat4.multiply(a, b, Float64Array);

// glm::translate(m, v) and glm::rotate(m, angle, axis) for a unit axis:
// m times the translation or rotation.
const translate = (m, v) => multiply(m, mat4.translation(v, Float64Array));
const rotate = (m, angle, axis) => multiply(m, mat4.rotation(angle, axis, Float64Array));

/**
 * The head's model matrix for FaceParams `params` (yaw, pitch, roll about the
 * neck pivot, translation in mm), standing at `place` (a room's seat; identity
 * if left out). Signs follow FaceParams: yaw toward the person's left, pitch up.
 */
export function headTransform(params, place = identity()) {
  const p = params ?? {};
  const t = p.head_translation_mm ?? [0, 0, 0];
  const shift = [0, 1, 2].map((k) => (t[k] ?? 0) / MILLIMETRES_PER_UNIT + NECK_PIVOT[k]);
  let m = translate(place, shift);
  m = rotate(m, p.head_yaw_rad ?? 0, [0, 1, 0]);
  m = rotate(m, -(p.head_pitch_rad ?? 0), [1, 0, 0]);
  m = rotate(m, -(p.head_roll_rad ?? 0), [0, 0, 1]);
  return translate(m, NECK_PIVOT.map((v) => -v));
}

/** An eyeball's rotation about its centre (yaw toward the person's left, pitch up). */
export function eyeTransform(centre, yawRad, pitchRad) {
  let m = translate(identity(), centre);
  m = rotate(m, yawRad, [0, 1, 0]);
  m = rotate(m, -pitchRad, [1, 0, 0]);
  return translate(m, [-centre[0], -centre[1], -centre[2]]);
}
