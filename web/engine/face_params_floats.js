// FaceParams (the decoder's objects: web/codec/decoder.js, field names of
// codec/include/fw/codec/face_params.hpp) as the 53 floats the WebAssembly
// model takes, in the codec's channel order (avatar/model/wasm/
// face_params_floats.hpp reads them back). A field left out counts as 0, so
// a hand-made pose such as { au: [...], lid_left: 1 } is a whole FaceParams.

export const AU_CHANNEL_COUNT = 29;
export const CORRECTIVE_COUNT = 6;
export const FACE_PARAMS_FLOATS = AU_CHANNEL_COUNT + 18 + CORRECTIVE_COUNT;

const number = (v) => (typeof v === 'number' && Number.isFinite(v) ? v : 0);

/** Writes `params` into `out` (a Float32Array of FACE_PARAMS_FLOATS) and returns it. */
export function faceParamsFloats(params, out = new Float32Array(FACE_PARAMS_FLOATS)) {
  const p = params ?? {};
  let i = 0;
  for (let c = 0; c < AU_CHANNEL_COUNT; ++c) out[i++] = number(p.au?.[c]);
  out[i++] = number(p.head_yaw_rad);
  out[i++] = number(p.head_pitch_rad);
  out[i++] = number(p.head_roll_rad);
  for (let k = 0; k < 3; ++k) out[i++] = number(p.head_translation_mm?.[k]);
  out[i++] = number(p.eye_left?.yaw_rad);
  out[i++] = number(p.eye_left?.pitch_rad);
  out[i++] = number(p.eye_right?.yaw_rad);
  out[i++] = number(p.eye_right?.pitch_rad);
  out[i++] = number(p.lid_left);
  out[i++] = number(p.lid_right);
  for (let k = 0; k < 5; ++k) out[i++] = number(p.blush?.[k]);
  out[i++] = number(p.pallor);
  for (let k = 0; k < CORRECTIVE_COUNT; ++k) out[i++] = number(p.corrective?.[k]);
  return out;
}
