// A face's aim moved from the server's room to the viewer's (PROTOCOL.md
// 6.1). The server aimed the face's eyes and head at its target's seat; the
// viewer sees it from elsewhere, with the target somewhere else. The decoded
// head and eyes are moved by the difference between the two aims, split the
// way the server's eye-head coordination splits a settled gaze
// (avatar/behavior's EyeHeadController: the eyes alone take the first 8
// degrees, the head 90 % of the rest), so that what the face does around its
// aim (saccades, drift, tremor, head noise) stays on top, and a face that
// attends the viewer ends with its head and eyes on the viewer: eye contact.
import { directionAngles, roomToSeat } from './view_geometry.js';

const HEAD_FREE_RAD = 0.14;
const HEAD_SHARE = 0.9;
const EYE_RANGE_RAD = 0.8;

/** The head's share of a settled gaze at angle `a` (one axis). */
export function headShare(a) {
  return Math.sign(a) * HEAD_SHARE * Math.max(0, Math.abs(a) - HEAD_FREE_RAD);
}

/**
 * How far a face turns toward another in the view, as a share of the true
 * angle. Every face of the view rests looking at the viewer, so its
 * neighbours sit nearly square to it: turned all the way it would show its
 * profile. A face turns at most to three-quarter, still clearly toward the
 * one it attends; at the viewer it looks straight out (that angle is ~0).
 */
export const TURN_SHARE = 0.6;

/** Yaw and pitch, in `seat`'s frame, from its eyes (`eyeMid`, head frame) to room point `target`. */
export function aimAt(seat, eyeMid, target) {
  const from = roomToSeat(seat, target);
  return directionAngles(from.map((v, i) => v - eyeMid[i]));
}

const clampEye = (v) => Math.max(-EYE_RANGE_RAD, Math.min(EYE_RANGE_RAD, v));
const mix = (a, b, t) => a + (b - a) * t;

/**
 * FaceParams `params` of a face that attends the viewer, turned onto the
 * viewer: the head straight at `viewAim` (no sway: the server's head lags
 * its gaze by an amount no rule here predicts, and any of it left in the
 * head would show as irises off the centre of the eyes), the eyes carrying
 * only what the gaze does around the server's aim, converged on the
 * viewer's distance (`vergenceRad` each) rather than on the server's target.
 */
export function reaimAtViewer(params, serverAim, viewAim, vergenceRad, weight = 1) {
  const fine = (axis, key) => params[key] + (params.eye_left[axis] + params.eye_right[axis]) / 2 - serverAim[axis === 'yaw_rad' ? 'yaw' : 'pitch'];
  const yaw = fine('yaw_rad', 'head_yaw_rad');
  const pitch = fine('pitch_rad', 'head_pitch_rad');
  // The person's right eye turns toward the person's left (+yaw) to converge.
  const eye = (e, inward) => ({
    yaw_rad: mix(e.yaw_rad, clampEye(yaw + inward * vergenceRad), weight),
    pitch_rad: mix(e.pitch_rad, clampEye(pitch), weight),
  });
  return {
    ...params,
    head_yaw_rad: mix(params.head_yaw_rad, viewAim.yaw, weight),
    head_pitch_rad: mix(params.head_pitch_rad, viewAim.pitch, weight),
    eye_right: eye(params.eye_right, 1),
    eye_left: eye(params.eye_left, -1),
  };
}

/** A face turned toward someone other than the viewer: the eyes' share of the turn. */
export const EYE_SHARE = 0.4;

/**
 * FaceParams `params` re-aimed: from `serverAim` to `viewAim` (each { yaw,
 * pitch } in the face's own seat frame), blended by `weight` (0: as decoded,
 * 1: fully re-aimed; the page eases it when the target changes). The head
 * leaves the server's settled share of its aim and takes 60 % of the new
 * one, the eyes the rest: a face turned toward a neighbour shows its eyes
 * turned that way too. Returns a new object; the decoded one is left alone.
 */
export function reaim(params, serverAim, viewAim, weight = 1) {
  const shift = (axis) => {
    const total = weight * (viewAim[axis] - serverAim[axis]);
    const head = weight * ((1 - EYE_SHARE) * viewAim[axis] - headShare(serverAim[axis]));
    return { head, eye: total - head };
  };
  const yaw = shift('yaw');
  const pitch = shift('pitch');
  const eye = (e) => ({ yaw_rad: clampEye(e.yaw_rad + yaw.eye), pitch_rad: clampEye(e.pitch_rad + pitch.eye) });
  return {
    ...params,
    head_yaw_rad: params.head_yaw_rad + yaw.head,
    head_pitch_rad: params.head_pitch_rad + pitch.head,
    eye_left: eye(params.eye_left),
    eye_right: eye(params.eye_right),
  };
}
