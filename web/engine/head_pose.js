// Head and eye matrices, as avatar/render/src/camera.cpp makes them
// (head_transform, eye_transform): column-major Float32Array(16), glm's and
// GLSL's layout. A port, not the same code (the renderer is not part of the
// WebAssembly module), so tests/model/wasm checks it against matrices the
// C++ wrote.

/** The point heads turn about (render::kNeckPivot): the top of the neck. */
export const NECK_PIVOT = [0, -1.5, 0.2];
/** Millimetres per model unit (model::kMillimetresPerUnit): head translation is in mm. */
export const MILLIMETRES_PER_UNIT = 63;

export const identity = () => new Float64Array([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]);

export function multiply(a, b) {
  const out = new Float64Array(16);
  for (let column = 0; column < 4; ++column) {
    for (let row = 0; row < 4; ++row) {
      let sum = 0;
      for (let k = 0; k < 4; ++k) sum += a[k * 4 + row] * b[column * 4 + k];
      out[column * 4 + row] = sum;
    }
  }
  return out;
}

// glm::translate(m, v) and glm::rotate(m, angle, axis) for a unit axis:
// m times the translation or rotation.
function translate(m, [x, y, z]) {
  const t = identity();
  t[12] = x;
  t[13] = y;
  t[14] = z;
  return multiply(m, t);
}

function rotate(m, angle, [x, y, z]) {
  const c = Math.cos(angle);
  const s = Math.sin(angle);
  const r = identity();
  r[0] = c + (1 - c) * x * x;
  r[1] = (1 - c) * x * y + s * z;
  r[2] = (1 - c) * x * z - s * y;
  r[4] = (1 - c) * y * x - s * z;
  r[5] = c + (1 - c) * y * y;
  r[6] = (1 - c) * y * z + s * x;
  r[8] = (1 - c) * z * x + s * y;
  r[9] = (1 - c) * z * y - s * x;
  r[10] = c + (1 - c) * z * z;
  return multiply(m, r);
}

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
