// A face turning to a new target in the view (web/room/retarget_easing.js):
// from where it was drawn, never through the stream's own aim.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import { RETARGET_S, RetargetEasing, aimOffset } from '../../../web/room/retarget_easing.js';

const DEG = Math.PI / 180;
const face = (headYawDeg, eyeYawDeg = 0) => ({
  head_yaw_rad: headYawDeg * DEG, head_pitch_rad: 0, head_roll_rad: 0,
  eye_left: { yaw_rad: eyeYawDeg * DEG, pitch_rad: 0 }, eye_right: { yaw_rad: eyeYawDeg * DEG, pitch_rad: 0 },
  au: [0.3],
});
const yawDeg = (p) => p.head_yaw_rad / DEG;
const near = (a, b, tolerance, what) => assert.ok(Math.abs(a - b) <= tolerance, `${what}: ${a} vs ${b}`);

test('a new target is turned to from where the face was drawn, not from the stream\'s aim', () => {
  const easing = new RetargetEasing();
  // The server's head turned 60 degrees to a neighbour; the view shows it at 30.
  const decoded = face(60);
  let drawn;
  for (let ms = 0; ms <= 1000; ms += 20) drawn = easing.params(7, 'a', decoded, face(30), ms);
  near(yawDeg(drawn), 30, 1e-9, 'settled on the first target');
  // Its target changes: in the view the new one is at 10 degrees. Each frame
  // moves a little; the first is where the last was.
  let last = yawDeg(drawn);
  let largest = 0;
  for (let ms = 1000; ms <= 1000 + RETARGET_S * 1000 + 100; ms += 20) {
    const now = yawDeg(easing.params(7, 'b', decoded, face(10), ms));
    largest = Math.max(largest, Math.abs(now - last));
    last = now;
  }
  near(last, 10, 1e-9, 'settled on the new target');
  assert.ok(largest < 3, `the head moves at most 3 degrees a frame (${largest.toFixed(2)}), never to the stream's 60`);
});

test('the re-aim rides on what the stream does, and a face seen first eases in from the stream', () => {
  const easing = new RetargetEasing();
  // The decoded face moves (saccade, head noise): the drawn one moves with it.
  const first = easing.params(1, 'x', face(20, 5), face(10, 2), 0);
  near(yawDeg(first), 20, 1e-9, 'first frame: the stream as it is');
  const settled = easing.params(1, 'x', face(25, 5), face(15, 2), 1000);
  near(yawDeg(settled), 15, 1e-9, 'settled: the full re-aim');
  assert.deepEqual(settled.au, [0.3], 'the expression is the stream\'s');
  const offset = aimOffset(settled, face(25, 5));
  near(offset.eye_left.yaw_rad / DEG, -3, 1e-9, 'the eyes carry their share');
  // Forgotten (muted, or gone): afresh from the stream.
  easing.forget(1);
  near(yawDeg(easing.params(1, 'x', face(25), face(15), 2000)), 25, 1e-9, 'afresh');
});

test('attending nobody here, the face eases back to the stream\'s own aim', () => {
  const easing = new RetargetEasing();
  for (let ms = 0; ms <= 1000; ms += 20) easing.params(2, 'a', face(40), face(20), ms);
  const start = yawDeg(easing.params(2, 'nobody', face(40), face(40), 1000));
  near(start, 20, 1e-9, 'no jump when the target goes');
  near(yawDeg(easing.params(2, 'nobody', face(40), face(40), 2000)), 40, 1e-9, 'then the stream\'s');
});
