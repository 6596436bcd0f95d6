// What the renderer needs for one face in one frame besides the skin's
// shape, as avatar/render makes it (face_draw in avatar_appearance.cpp,
// draw_face in face_renderer.cpp): the head's model matrix, each eyeball's,
// the lid closures for the closed-lid skin, and the blood colour.
import { eyeTransform, headTransform, multiply } from './head_pose.js';

/**
 * @param params  FaceParams (decoder field names)
 * @param eyeCentres  [right, left] eyeball centres of the avatar's face (model units)
 * @param [place]  the seat's matrix (column-major, 16 numbers); identity if left out
 */
export function faceDraw(params, eyeCentres, place) {
  const p = params ?? {};
  const head = headTransform(p, place);
  // Indexed by side as everywhere in facewire: 0 the person's right, 1 left.
  const gaze = [p.eye_right ?? {}, p.eye_left ?? {}];
  const eyeYawPitch = gaze.map((e) => [e.yaw_rad ?? 0, e.pitch_rad ?? 0]);
  const eyeModels = eyeCentres.map((centre, side) =>
    Float32Array.from(multiply(head, eyeTransform(centre, ...eyeYawPitch[side]))));
  const blush = Array.from({ length: 5 }, (_, k) => p.blush?.[k] ?? 0);
  const pallor = p.pallor ?? 0;
  return {
    /** u_model of the skin, the mouth cavity and the head shell. */
    model: Float32Array.from(head),
    /** u_model of each eyeball: [right, left]. */
    eyeModels,
    /** Each eye's [yaw, pitch] in radians: [right, left]. */
    eyeYawPitch,
    /** u_lid_closure: [right, left], 0 open .. 1 closed (the closed-lid skin's weight). */
    lidClosure: [p.lid_right ?? 0, p.lid_left ?? 0],
    /** u_blush_a = blush[0..3] (forehead, cheek_left, cheek_right, nose), u_blush_sides = blush[4]. */
    blush,
    /** u_pallor. */
    pallor,
    /** Whether the skin needs the shader variant with blood colour (the native renderer skips it otherwise). */
    blood: blush.some((b) => b > 0) || pallor > 0,
  };
}
