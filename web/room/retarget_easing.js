// A face turning to a new target in the view, eased from where it was drawn.
// The re-aim (gaze_reaim.js) is what the view adds to the decoded head and
// eyes; when the target changes, that addition moves from the one last drawn
// to the new target's over RETARGET_S. Eased from nothing instead, a face
// showed the stream's own aim (the server's room, where a neighbour may sit
// 60 degrees away) for a frame at every change of target, then turned back.

/** How long a face takes to turn to a new target in the view (s): the server's head moves as smoothly. */
export const RETARGET_S = 0.35;

const AXES = ['yaw_rad', 'pitch_rad'];
const EYES = ['eye_left', 'eye_right'];

/** What `params` adds to `decoded`: the head's yaw and pitch, each eye's yaw and pitch. */
export function aimOffset(params, decoded) {
  const eye = (key) => Object.fromEntries(AXES.map((a) => [a, params[key][a] - decoded[key][a]]));
  return {
    head_yaw_rad: params.head_yaw_rad - decoded.head_yaw_rad,
    head_pitch_rad: params.head_pitch_rad - decoded.head_pitch_rad,
    eye_left: eye('eye_left'),
    eye_right: eye('eye_right'),
  };
}

const ZERO = {
  head_yaw_rad: 0, head_pitch_rad: 0, eye_left: { yaw_rad: 0, pitch_rad: 0 }, eye_right: { yaw_rad: 0, pitch_rad: 0 },
};

function mixOffsets(a, b, t) {
  const m = (x, y) => x + (y - x) * t;
  const eye = (key) => Object.fromEntries(AXES.map((ax) => [ax, m(a[key][ax], b[key][ax])]));
  return { head_yaw_rad: m(a.head_yaw_rad, b.head_yaw_rad), head_pitch_rad: m(a.head_pitch_rad, b.head_pitch_rad),
    eye_left: eye('eye_left'), eye_right: eye('eye_right') };
}

/** `decoded` with `offset` added; a new object. */
export function withOffset(decoded, offset) {
  const eye = (key) => Object.fromEntries(AXES.map((a) => [a, decoded[key][a] + offset[key][a]]));
  return {
    ...decoded,
    head_yaw_rad: decoded.head_yaw_rad + offset.head_yaw_rad,
    head_pitch_rad: decoded.head_pitch_rad + offset.head_pitch_rad,
    ...Object.fromEntries(EYES.map((key) => [key, eye(key)])),
  };
}

/** Each face's re-aim, eased between targets. */
export class RetargetEasing {
  constructor() {
    this.faces = new Map();  // avatar id -> { key, since, from, last }
  }

  /**
   * What face `id` is drawn with at `nowMs`: `decoded` re-aimed toward `full`
   * (decoded re-aimed in full at the target named `key`; decoded itself when
   * it attends nobody here). A face seen for the first time eases in from
   * the stream's own aim.
   */
  params(id, key, decoded, full, nowMs) {
    let face = this.faces.get(id);
    if (!face || face.key !== key) {
      face = { key, since: nowMs, from: face ? face.last : ZERO, last: null };
      this.faces.set(id, face);
    }
    const t = Math.min(1, (nowMs - face.since) / 1000 / RETARGET_S);
    face.last = mixOffsets(face.from, aimOffset(full, decoded), t * t * (3 - 2 * t));
    return withOffset(decoded, face.last);
  }

  /** Face `id` is drawn without a re-aim (muted) or is gone: it starts afresh. */
  forget(id) {
    this.faces.delete(id);
  }
}
